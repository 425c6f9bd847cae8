// STUDENT COPY of solutions/ch16_depth_of_field.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 16 exercises: depth of field (book §16, course §9.11.3). Declared in
// common/render/camera.hpp.
#include "core/exercise.hpp"
#include "render/camera.hpp"

#include <cmath>
#include <numbers>

// @helpers
// Your #includes and helper functions, if any (inside namespace rt { ... } to use the
// library's names unqualified). ./lab exercises keeps these lines like an exercise body.
// @end

namespace rt {

Vec2 lens_point(const Vec2& u, LensShape shape) {
    RT_STUDENT_EXERCISE(16, 1);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 16.1 | lens_point | book §16.2
    throw NotImplemented("exercise 16.1 (lens_point) is not done yet: see book §16.2");
    // @end
}

Ray thin_lens_ray(const Vec3& eye, const Basis& uvw, Real d, const Vec2& uv, Real aperture, Real focus,
                  const Vec2& lens) {
    RT_STUDENT_EXERCISE(16, 2);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 16.2 | thin_lens_ray | book §16.1
    throw NotImplemented("exercise 16.2 (thin_lens_ray) is not done yet: see book §16.1");
    // @end
}

}  // namespace rt
