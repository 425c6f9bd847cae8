// STUDENT COPY of solutions/ch15_soft_shadows.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 15 exercises: soft shadows (book §15, course §9.11.2). Declared in
// common/core/sampler.hpp and common/shading/light.hpp.
#include "core/exercise.hpp"
#include "core/sampler.hpp"
#include "shading/light.hpp"

#include <utility>

// @helpers
// Your #includes and helper functions, if any (inside namespace rt { ... } to use the
// library's names unqualified). ./lab exercises keeps these lines like an exercise body.
// @end

namespace rt {

void fisher_yates(std::vector<std::uint32_t>& order, pcg32& random) {
    RT_STUDENT_EXERCISE(15, 1);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 15.1 | fisher_yates | book §15.2
    throw NotImplemented("exercise 15.1 (fisher_yates) is not done yet: see book §15.2");
    // @end
}

Vec3 light_point(const Light& light, const Vec2& uv) {
    RT_STUDENT_EXERCISE(15, 2);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 15.2 | light_point | book §15.1
    throw NotImplemented("exercise 15.2 (light_point) is not done yet: see book §15.1");
    // @end
}

}  // namespace rt
