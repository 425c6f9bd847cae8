// fairness 1.3 pass: the window point's offset summed first, then added to the eye
// @body
    const Vec3 offset = uv.x * uvw.u + uv.y * uvw.v;
    return Ray{eye + offset, -uvw.w};
