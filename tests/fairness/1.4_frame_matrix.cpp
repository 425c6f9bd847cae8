// fairness 1.4 pass: the direction as the frame's matrix [u v w] times (u_s, v_s, -d)
// @body
    return Ray{eye, glm::mat<3, 3, Real>(uvw.u, uvw.v, uvw.w) * Vec3(uv.x, uv.y, -d)};
