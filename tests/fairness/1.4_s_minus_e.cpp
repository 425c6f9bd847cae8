// fairness 1.4 fail: the direction as s - e, with s = e + u_s u + v_s v - d w computed first
// The same vector in exact arithmetic, but adding the eye and taking it away again keeps only
// the digits the eye's size leaves: a camera 10^5 from the origin loses ten of them.
// @body
    const Vec3 s = eye + uv.x * uvw.u + uv.y * uvw.v - d * uvw.w;
    return Ray{eye, s - eye};
