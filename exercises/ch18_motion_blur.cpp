// STUDENT COPY of solutions/ch18_motion_blur.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 18 exercises: motion blur (book §18, course §9.11.5). Declared in
// common/render/camera.hpp and common/geometry/sphere.hpp.
#include "core/exercise.hpp"
#include "geometry/sphere.hpp"
#include "render/camera.hpp"

#include <algorithm>
#include <cmath>

// @helpers
// Your #includes and helper functions, if any (inside namespace rt { ... } to use the
// library's names unqualified). ./lab exercises keeps these lines like an exercise body.
// @end

namespace rt {

Real shutter_time(int k, int n, Real u, Real open, Real close) {
    RT_STUDENT_EXERCISE(18, 1);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 18.1 | shutter_time | book §18.2
    throw NotImplemented("exercise 18.1 (shutter_time) is not done yet: see book §18.2");
    // @end
}

Box swept_box(const Sphere& sphere) {
    RT_STUDENT_EXERCISE(18, 2);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 18.2 | swept_box | book §18.1
    throw NotImplemented("exercise 18.2 (swept_box) is not done yet: see book §18.1");
    // @end
}

}  // namespace rt
