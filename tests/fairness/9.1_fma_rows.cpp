// fairness 9.1 pass: each coordinate with fused multiply-adds along a row of M^-1
// @helpers
#include <cmath>
// @body
    const Mat3& m = to_object.m;  // column-major: m[column][row]
    Vec3 origin, direction;
    for (int row = 0; row < 3; ++row) {
        origin[row] = std::fma(m[2][row], ray.origin.z,
                               std::fma(m[1][row], ray.origin.y, std::fma(m[0][row], ray.origin.x, to_object.t[row])));
        direction[row] = std::fma(m[2][row], ray.direction.z,
                                  std::fma(m[1][row], ray.direction.y, m[0][row] * ray.direction.x));
    }
    return Ray{origin, direction, ray.time};
