// STUDENT COPY of solutions/ch07_specular_reflection.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 07 exercises: specular reflection (book §7, course §9.6). Declared in
// common/shading/optics.hpp.
#include "core/exercise.hpp"
#include "shading/optics.hpp"

// @helpers
// Your #includes and helper functions, if any (inside namespace rt { ... } to use the
// library's names unqualified). ./lab exercises keeps these lines like an exercise body.
// @end

namespace rt {

Vec3 reflect(const Vec3& d, const Vec3& n) {
    RT_STUDENT_EXERCISE(7, 1);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 7.1 | reflect | book §7.1
    throw NotImplemented("exercise 7.1 (reflect) is not done yet: see book §7.1");
    // @end
}

}  // namespace rt
