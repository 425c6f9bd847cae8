// STUDENT COPY of solutions/ch04_polygons.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 04 exercises: ray-polygon intersection (book §4, course §9.3.3). Declared in
// common/geometry/polygon.hpp.
#include "core/exercise.hpp"
#include "geometry/polygon.hpp"

#include <cmath>

namespace rt {

// @book axes
std::array<int, 2> projection_axes(const Vec3& n) {
    // @exercise 4.1 | projection_axes | book §4.2
    throw NotImplemented("exercise 4.1 (projection_axes) is not done yet: see book §4.2");
    // @end
}
// @book-end

// @book crossing
bool inside_polygon_2d(const std::vector<Vec2>& polygon, const Vec2& p) {
    // @exercise 4.2 | inside_polygon_2d | book §4.3
    throw NotImplemented("exercise 4.2 (inside_polygon_2d) is not done yet: see book §4.3");
    // @end
}
// @book-end

// @book polygon-hit
bool hit(const Polygon& polygon, const Ray& ray, Interval interval, PolygonHit& result) {
    // @exercise 4.3 | hit(Polygon) | book §4.4
    throw NotImplemented("exercise 4.3 (hit(Polygon)) is not done yet: see book §4.4");
    // @end
}
// @book-end

}  // namespace rt
