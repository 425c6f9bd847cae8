// Chapter 17 exercises: glossy reflection (book §17, course §9.11.4). Declared in
// common/shading/optics.hpp.
#include "core/exercise.hpp"
#include "shading/optics.hpp"

#include <cmath>

namespace rt {

// @book glossy
Vec3 glossy_direction(const Vec3& r, Real width, const Vec2& uv) {
    // @exercise 17.1 | glossy_direction | book §17.1
    // A frame square to r: cross r with the axis it leans on least (the course's t: r with
    // its smallest component set to 1 works the same way), then r x u.
    const Vec3 a = std::abs(r.x) <= std::abs(r.y) && std::abs(r.x) <= std::abs(r.z) ? Vec3(1, 0, 0)
                   : std::abs(r.y) <= std::abs(r.z)                                 ? Vec3(0, 1, 0)
                                                                                    : Vec3(0, 0, 1);
    const Vec3 u = glm::normalize(glm::cross(a, r));
    const Vec3 v = glm::cross(r, u);
    return r + (uv.x - Real(0.5)) * width * u + (uv.y - Real(0.5)) * width * v;
    // @end
}
// @book-end

}  // namespace rt
