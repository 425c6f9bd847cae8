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

inline const char* real_name() {
    return sizeof(Real) == sizeof(float) ? "float" : "double";
}

}  // namespace rt
