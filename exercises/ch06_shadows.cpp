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

namespace rt {

// @book offset
Vec3 offset_origin(const Vec3& p, const Vec3& n) {
    // @exercise 6.1 | offset_origin | book §6.3
    throw NotImplemented("exercise 6.1 (offset_origin) is not done yet: see book §6.3");
    // @end
}
// @book-end

// @book direct
Color direct_light(const Scene& scene, const Light& light, int light_index, const ShadePoint& sp,
                   TraceContext& context) {
    // @exercise 6.2 | direct_light | book §6.2
    throw NotImplemented("exercise 6.2 (direct_light) is not done yet: see book §6.2");
    // @end
}
// @book-end

}  // namespace rt
