// STUDENT COPY of solutions/ch11_grid.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 11 exercises: the uniform grid (book §11, course §9.9.3). Declared in
// common/accel/grid.hpp.
#include "accel/grid.hpp"
#include "core/exercise.hpp"

#include <algorithm>
#include <cmath>

// @helpers
// Your #includes and helper functions, if any (inside namespace rt { ... } to use the
// library's names unqualified). ./lab exercises keeps these lines like an exercise body.
// @end

namespace rt {

bool Grid::start(const Ray& ray, Interval interval, GridWalk& walk) const {
    RT_STUDENT_EXERCISE(11, 1);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 11.1 | Grid::start | book §11.2
    throw NotImplemented("exercise 11.1 (Grid::start) is not done yet: see book §11.2");
    // @end
}

bool Grid::walk(const SurfaceList& surfaces, const Ray& ray, Interval interval, HitRecord& best) const {
    RT_STUDENT_EXERCISE(11, 2);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 11.2 | Grid::walk | book §11.3
    throw NotImplemented("exercise 11.2 (Grid::walk) is not done yet: see book §11.3");
    // @end
}

}  // namespace rt
