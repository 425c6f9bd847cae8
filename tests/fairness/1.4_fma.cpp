// fairness 1.4 pass: each coordinate of the direction with fused multiply-adds
// @helpers
#include <cmath>
// @body
    Vec3 direction;
    for (int i = 0; i < 3; ++i) direction[i] = std::fma(uv.x, uvw.u[i], std::fma(uv.y, uvw.v[i], -d * uvw.w[i]));
    return Ray{eye, direction};
