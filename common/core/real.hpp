#pragma once
// The scalar type of all geometry, chosen at configure time (-DRTLAB_REAL=float|double).
// Colours stay float whatever Real is: they carry no geometric precision.
#include <glm/glm.hpp>

#include <limits>

namespace rt {

#if defined(RTLAB_REAL_FLOAT)
using Real = float;
#else
using Real = double;
#endif

// @book vec3
using Vec2 = glm::vec<2, Real, glm::defaultp>;
using Vec3 = glm::vec<3, Real, glm::defaultp>;
using Color = glm::vec3;  // linear RGB

inline constexpr Real kInfinity = std::numeric_limits<Real>::infinity();

// v / |v|, scaled by its largest component first so that |v|^2 neither overflows (1e20 in
// float) nor underflows (1e-20): any finite non-zero vector gives a unit vector. Zero for
// the zero vector.
inline Vec3 unit_vector(const Vec3& v) {
    const Real m = glm::max(glm::max(glm::abs(v.x), glm::abs(v.y)), glm::abs(v.z));
    if (!(m > 0)) return Vec3(0);
    const Vec3 s = v / m;
    return s / glm::sqrt(glm::dot(s, s));
}
// @book-end

inline const char* real_name() {
    return sizeof(Real) == sizeof(float) ? "float" : "double";
}

}  // namespace rt
