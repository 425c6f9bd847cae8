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

// x rounded to the nearest float, as a Real. Written out because GCC 12.2 (Debian 12's)
// miscompiles the plain `Real(float(x))` when it vectorises two or more of them side by
// side: the narrowing and the widening are folded away and x comes back unrounded (wrong
// code from -O2 on; tests/test_common.cpp checks this). The empty asm hides the float from the folding.
inline Real round_to_float(Real x) {
    float f = float(x);
    asm("" : "+x"(f));
    return Real(f);
}

inline const char* real_name() {
    return sizeof(Real) == sizeof(float) ? "float" : "double";
}

}  // namespace rt
