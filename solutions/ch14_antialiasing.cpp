// Chapter 14 exercises: antialiasing (book §14, course §9.11.1). Declared in
// common/render/antialiasing.hpp.
#include "core/exercise.hpp"
#include "render/antialiasing.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

// @book stratified
Vec2 stratified_point(int k, int n, Vec2 u) {
    // @exercise 14.1 | stratified_point | book §14.2
    const int sx = k % n, sy = k / n;
    // (n - 1 + u) / n rounds to 1 for u just below 1: keep the result inside [0, 1).
    const Real below_one = std::nextafter(Real(1), Real(0));
    return Vec2(std::min((Real(sx) + u.x) / Real(n), below_one), std::min((Real(sy) + u.y) / Real(n), below_one));
    // @end
}
// @book-end

// @book tent
Real tent_offset(Real u) {
    // @exercise 14.2 | tent_offset | book §14.3
    // The tent's distribution function is (1 + x)^2 / 2 on the left half and
    // 1 - (1 - x)^2 / 2 on the right: invert each half.
    return u < Real(0.5) ? std::sqrt(2 * u) - 1 : 1 - std::sqrt(2 - 2 * u);
    // @end
}
// @book-end

}  // namespace rt
