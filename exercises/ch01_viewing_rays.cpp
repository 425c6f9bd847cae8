// STUDENT COPY of solutions/ch01_viewing_rays.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 01 exercises: viewing rays (book §1, course §9.2). Declared in common/render/camera.hpp.
#include "core/exercise.hpp"
#include "render/camera.hpp"

// @helpers
// Your #includes and helper functions, if any (inside namespace rt { ... } to use the
// library's names unqualified). ./lab exercises keeps these lines like an exercise body.
// @end

namespace rt {

Basis camera_basis(const Vec3& view_direction, const Vec3& up) {
    RT_STUDENT_EXERCISE(1, 1);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 1.1 | camera_basis | book §1.2
    throw NotImplemented("exercise 1.1 (camera_basis) is not done yet: see book §1.2");
    // @end
}

Vec2 window_point(Real x, Real y, int nx, int ny, const Window& win) {
    RT_STUDENT_EXERCISE(1, 2);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 1.2 | window_point | book §1.3
    throw NotImplemented("exercise 1.2 (window_point) is not done yet: see book §1.3");
    // @end
}

Ray orthographic_ray(const Vec3& eye, const Basis& uvw, const Vec2& uv) {
    RT_STUDENT_EXERCISE(1, 3);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 1.3 | orthographic_ray | book §1.4
    throw NotImplemented("exercise 1.3 (orthographic_ray) is not done yet: see book §1.4");
    // @end
}

Ray perspective_ray(const Vec3& eye, const Basis& uvw, Real d, const Vec2& uv) {
    RT_STUDENT_EXERCISE(1, 4);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 1.4 | perspective_ray | book §1.4
    throw NotImplemented("exercise 1.4 (perspective_ray) is not done yet: see book §1.4");
    // @end
}

}  // namespace rt
