// STUDENT COPY of solutions/ch04_polygons.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 04 exercises: ray-polygon intersection (book §4, course §9.3.3). Declared in
// common/geometry/polygon.hpp.
#include "core/exercise.hpp"
#include "geometry/polygon.hpp"

#include <cmath>

// @helpers
// Your #includes and helper functions, if any (inside namespace rt { ... } to use the
// library's names unqualified). ./lab exercises keeps these lines like an exercise body.
// @end

namespace rt {

std::array<int, 2> projection_axes(const Vec3& n) {
    RT_STUDENT_EXERCISE(4, 1);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 4.1 | projection_axes | book §4.2
    throw NotImplemented("exercise 4.1 (projection_axes) is not done yet: see book §4.2");
    // @end
}

// The contract (geometry/polygon.hpp, book §4.3): the crossing number with the half-open
// boundary rule, and a shared edge's crossing computed to the same bits by both polygons
// that share it, whichever way each walks it: then every point on or ulps away from a shared
// edge is inside exactly one of the two.
bool inside_polygon_2d(const std::vector<Vec2>& polygon, const Vec2& p) {
    RT_STUDENT_EXERCISE(4, 2);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 4.2 | inside_polygon_2d | book §4.3
    throw NotImplemented("exercise 4.2 (inside_polygon_2d) is not done yet: see book §4.3");
    // @end
}

bool hit(const Polygon& polygon, const Ray& ray, Interval interval, PolygonHit& result) {
    RT_STUDENT_EXERCISE(4, 3);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 4.3 | hit(Polygon) | book §4.4
    throw NotImplemented("exercise 4.3 (hit(Polygon)) is not done yet: see book §4.4");
    // @end
}

}  // namespace rt
