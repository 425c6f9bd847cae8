// STUDENT COPY of solutions/ch10_bvh.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 10 exercises: bounding boxes and the bounding volume hierarchy (book §10, course
// §9.9.1-9.9.2). Declared in common/accel/course_bvh.hpp.
#include "accel/course_bvh.hpp"
#include "core/exercise.hpp"

#include <algorithm>
#include <cmath>

// @helpers
// Your #includes and helper functions, if any (inside namespace rt { ... } to use the
// library's names unqualified). ./lab exercises keeps these lines like an exercise body.
// @end

namespace rt {

bool hit_box(const Box& box, const Ray& ray, Interval interval) {
    RT_STUDENT_EXERCISE(10, 1);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 10.1 | hit_box | book §10.1
    throw NotImplemented("exercise 10.1 (hit_box) is not done yet: see book §10.1");
    // @end
}

BvhRef build_sorted(BvhBuilder& builder, std::span<std::uint32_t> primitives, int axis) {
    RT_STUDENT_EXERCISE(10, 2);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 10.2 | build_sorted | book §10.3
    throw NotImplemented("exercise 10.2 (build_sorted) is not done yet: see book §10.3");
    // @end
}

BvhRef build_midpoint(BvhBuilder& builder, std::span<std::uint32_t> primitives, int axis) {
    RT_STUDENT_EXERCISE(10, 3);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 10.3 | build_midpoint | book §10.3
    throw NotImplemented("exercise 10.3 (build_midpoint) is not done yet: see book §10.3");
    // @end
}

bool Bvh::hit_node(const SurfaceList& surfaces, BvhRef ref, const Ray& ray, Interval interval, HitRecord& best) const {
    RT_STUDENT_EXERCISE(10, 4);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 10.4 | Bvh::hit_node | book §10.4
    throw NotImplemented("exercise 10.4 (Bvh::hit_node) is not done yet: see book §10.4");
    // @end
}

}  // namespace rt
