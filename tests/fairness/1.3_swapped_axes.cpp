// fairness 1.3 fail: u_s along v and v_s along u: the image turned on its diagonal
// @body
    return Ray{eye + uv.x * uvw.v + uv.y * uvw.u, -uvw.w};
