// STUDENT COPY of solutions/ch03_triangles.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 03 exercises: ray-triangle intersection (book §3, course §9.3.2). Declared in
// common/geometry/triangle.hpp.
#include "core/exercise.hpp"
#include "geometry/triangle.hpp"

#include <cmath>
#include <type_traits>
#include <utility>

// @helpers
// Your #includes and helper functions, if any (inside namespace rt { ... } to use the
// library's names unqualified). ./lab exercises keeps these lines like an exercise body.
// @end

namespace rt {

bool ray_triangle(const Ray& ray, const Vec3& A, const Vec3& B, const Vec3& C, Interval interval, TriangleHit& result) {
    RT_STUDENT_EXERCISE(3, 1);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 3.1 | ray_triangle | book §3.2
    throw NotImplemented("exercise 3.1 (ray_triangle) is not done yet: see book §3.2");
    // @end
}

bool ray_triangle_watertight(const Ray& ray, const Vec3& A, const Vec3& B, const Vec3& C, Interval interval,
                             TriangleHit& result) {
    RT_STUDENT_EXERCISE(3, 2);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 3.2 | ray_triangle_watertight | book §3.4
    throw NotImplemented("exercise 3.2 (ray_triangle_watertight) is not done yet: see book §3.4");
    // @end
}

}  // namespace rt
