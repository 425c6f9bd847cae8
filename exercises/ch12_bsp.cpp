// STUDENT COPY of solutions/ch12_bsp.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 12 exercises: the binary space partitioning tree (book §12, course §9.9.4).
// Declared in common/accel/bsp.hpp.
#include "accel/bsp.hpp"
#include "core/exercise.hpp"

#include <algorithm>
#include <cmath>

// @helpers
// Your #includes and helper functions, if any (inside namespace rt { ... } to use the
// library's names unqualified). ./lab exercises keeps these lines like an exercise body.
// @end

namespace rt {

bool Bsp::hit_node(const SurfaceList& surfaces, BspRef ref, const Ray& ray, Interval interval, HitRecord& best) const {
    RT_STUDENT_EXERCISE(12, 1);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 12.1 | Bsp::hit_node | book §12.2
    throw NotImplemented("exercise 12.1 (Bsp::hit_node) is not done yet: see book §12.2");
    // @end
}

BspRef build_midpoint(BspBuilder& builder, std::span<const std::uint32_t> items, const Box& cell, int depth) {
    RT_STUDENT_EXERCISE(12, 2);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 12.2 | build_midpoint | book §12.4
    throw NotImplemented("exercise 12.2 (build_midpoint) is not done yet: see book §12.4");
    // @end
}

}  // namespace rt
