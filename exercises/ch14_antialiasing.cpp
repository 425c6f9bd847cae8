// STUDENT COPY of solutions/ch14_antialiasing.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 14 exercises: antialiasing (book §14, course §9.11.1). Declared in
// common/render/antialiasing.hpp.
#include "core/exercise.hpp"
#include "render/antialiasing.hpp"

#include <algorithm>
#include <cmath>

// @helpers
// Your #includes and helper functions, if any (inside namespace rt { ... } to use the
// library's names unqualified). ./lab exercises keeps these lines like an exercise body.
// @end

namespace rt {

Vec2 stratified_point(int k, int n, Vec2 u) {
    RT_STUDENT_EXERCISE(14, 1);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 14.1 | stratified_point | book §14.2
    throw NotImplemented("exercise 14.1 (stratified_point) is not done yet: see book §14.2");
    // @end
}

Real tent_offset(Real u) {
    RT_STUDENT_EXERCISE(14, 2);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 14.2 | tent_offset | book §14.3
    throw NotImplemented("exercise 14.2 (tent_offset) is not done yet: see book §14.3");
    // @end
}

}  // namespace rt
