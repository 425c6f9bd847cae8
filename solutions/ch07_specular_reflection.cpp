// Chapter 07 exercises: specular reflection (book §7, course §9.6). Declared in
// common/shading/optics.hpp.
#include "core/exercise.hpp"
#include "shading/optics.hpp"

namespace rt {

// @book reflect
Vec3 reflect(const Vec3& d, const Vec3& n) {
    // @exercise 7.1 | reflect | book §7.1
    // Take away d's component along n twice: once to reach the surface's plane, once more
    // to come back out. The sign of n does not matter, its length does.
    return d - 2 * glm::dot(d, n) * n;
    // @end
}
// @book-end

}  // namespace rt
