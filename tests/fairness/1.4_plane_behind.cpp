// fairness 1.4 fail: the image plane at +d w, behind the eye
// @body
    return Ray{eye, uv.x * uvw.u + uv.y * uvw.v + d * uvw.w};
