// fairness 7.1 pass: each coordinate as one fused multiply-add, d_i + (-2 d.n) n_i
// @helpers
#include <cmath>
// @body
    const Real k = -2 * glm::dot(d, n);
    return Vec3(std::fma(k, n.x, d.x), std::fma(k, n.y, d.y), std::fma(k, n.z, d.z));
