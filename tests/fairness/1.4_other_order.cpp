// fairness 1.4 pass: -d w first, then the window point's offset
// @body
    return Ray{eye, -d * uvw.w + uv.x * uvw.u + uv.y * uvw.v};
