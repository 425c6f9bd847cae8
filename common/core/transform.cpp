#include "core/transform.hpp"

#include <cmath>
#include <stdexcept>

namespace rt {

Affine Affine::rotate(const Vec3& axis, Real degrees) {
    // Rodrigues' formula: R = cos I + sin [k]x + (1 - cos) k k^T, columns first (glm).
    const Vec3 k = unit_vector(axis);
    const Real a = glm::radians(degrees), c = std::cos(a), s = std::sin(a), C = 1 - c;
    const Mat3 r(c + k.x * k.x * C, k.y * k.x * C + k.z * s, k.z * k.x * C - k.y * s,   // column 0
                 k.x * k.y * C - k.z * s, c + k.y * k.y * C, k.z * k.y * C + k.x * s,   // column 1
                 k.x * k.z * C + k.y * s, k.y * k.z * C - k.x * s, c + k.z * k.z * C);  // column 2
    return Affine{r, Vec3(0)};
}

Affine inverse(const Affine& a, const std::string& what) {
    const std::string prefix = what.empty() ? "" : what + ": ";
    // Scale-free test: the determinant against the product of the column lengths, which it
    // equals for an orthogonal matrix and which bounds it always (Hadamard). A ratio under
    // 1e-12 means one direction is squeezed a trillion times more than another.
    const Real det = glm::determinant(a.m);
    const Real bound = glm::length(a.m[0]) * glm::length(a.m[1]) * glm::length(a.m[2]);
    if (!std::isfinite(det) || !(std::abs(det) > Real(1e-12) * bound))
        throw std::invalid_argument(prefix + "singular transform (it flattens space, so it has no inverse)");
    Affine inv;
    inv.m = glm::inverse(a.m);
    inv.t = -(inv.m * a.t);
    // Near-singular: the condition number (Frobenius norms, 3 for a rotation) past 3 x 10^6. Rays
    // taken into such a space grow by as much, and a coordinate of 10^8 (limits.hpp) would
    // leave float's range in the products of the ray tests.
    Real norm = 0, inv_norm = 0;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) {
            norm += a.m[c][r] * a.m[c][r];
            inv_norm += inv.m[c][r] * inv.m[c][r];
        }
    const Real condition = std::sqrt(norm) * std::sqrt(inv_norm);
    if (!std::isfinite(condition) || condition > Real(3e6))
        throw std::invalid_argument(prefix +
                                    "nearly singular transform (it squeezes one direction over a million "
                                    "times more than another)");
    return inv;
}

}  // namespace rt
