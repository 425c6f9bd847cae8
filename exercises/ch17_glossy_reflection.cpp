// STUDENT COPY of solutions/ch17_glossy_reflection.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 17 exercises: glossy reflection (book §17, course §9.11.4). Declared in
// common/shading/optics.hpp.
#include "core/exercise.hpp"
#include "shading/optics.hpp"

#include <cmath>

// @helpers
// Your #includes and helper functions, if any (inside namespace rt { ... } to use the
// library's names unqualified). ./lab exercises keeps these lines like an exercise body.
// @end

namespace rt {

Vec3 glossy_direction(const Vec3& r, Real width, const Vec2& uv) {
    RT_STUDENT_EXERCISE(17, 1);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 17.1 | glossy_direction | book §17.1
    throw NotImplemented("exercise 17.1 (glossy_direction) is not done yet: see book §17.1");
    // @end
}

}  // namespace rt
