// fairness 1.3 pass: the offset as the frame's matrix [u v w] times (u_s, v_s, 0)
// @body
    const glm::mat<3, 3, Real> frame(uvw.u, uvw.v, uvw.w);
    return Ray{eye + frame * Vec3(uv.x, uv.y, 0), Real(-1) * uvw.w};
