// fairness 1.3 fail: the direction +w: the eye looks down -w, so these rays leave the scene
// @body
    return Ray{eye + uv.x * uvw.u + uv.y * uvw.v, uvw.w};
