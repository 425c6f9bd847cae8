// fairness 1.4 fail: the image plane at distance 1 whatever d is
// Right for the scenes with focal distance 1, but the field of view of every other is off.
// @body
    return Ray{eye, uv.x * uvw.u + uv.y * uvw.v - uvw.w};
