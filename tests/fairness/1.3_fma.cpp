// fairness 1.3 pass: each coordinate of the origin with two fused multiply-adds
// @helpers
#include <cmath>
// @body
    Vec3 origin;
    for (int i = 0; i < 3; ++i) origin[i] = std::fma(uv.y, uvw.v[i], std::fma(uv.x, uvw.u[i], eye[i]));
    return Ray{origin, -uvw.w};
