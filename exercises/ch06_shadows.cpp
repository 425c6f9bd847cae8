// STUDENT COPY of solutions/ch06_shadows.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 06 exercises: shadows (book §6, course §9.5). Declared in common/core/offset.hpp
// and common/render/whitted.hpp.
#include "core/exercise.hpp"
#include "core/offset.hpp"
#include "render/scene.hpp"
#include "render/whitted.hpp"
#include "shading/shading.hpp"

#include <bit>
#include <cmath>

// @helpers
// Your #includes and helper functions, if any (inside namespace rt { ... } to use the
// library's names unqualified). ./lab exercises keeps these lines like an exercise body.
// @end

namespace rt {

Vec3 offset_origin(const Vec3& p, const Vec3& n) {
    RT_STUDENT_EXERCISE(6, 1);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 6.1 | offset_origin | book §6.3
    throw NotImplemented("exercise 6.1 (offset_origin) is not done yet: see book §6.3");
    // @end
}

Color direct_light(const Scene& scene, const Light& light, int light_index, const ShadePoint& sp,
                   TraceContext& context) {
    RT_STUDENT_EXERCISE(6, 2);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 6.2 | direct_light | book §6.2
    throw NotImplemented("exercise 6.2 (direct_light) is not done yet: see book §6.2");
    // @end
}

}  // namespace rt
