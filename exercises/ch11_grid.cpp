// STUDENT COPY of solutions/ch11_grid.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 11 exercises: the uniform grid (book §11, course §9.9.3). Declared in
// common/accel/grid.hpp.
#include "accel/grid.hpp"
#include "core/exercise.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

// @book start
bool Grid::start(const Ray& ray, Interval interval, GridWalk& walk) const {
    // @exercise 11.1 | Grid::start | book §11.2
    throw NotImplemented("exercise 11.1 (Grid::start) is not done yet: see book §11.2");
    // @end
}
// @book-end

// @book walk
bool Grid::walk(const SurfaceList& surfaces, const Ray& ray, Interval interval, HitRecord& best) const {
    // @exercise 11.2 | Grid::walk | book §11.3
    throw NotImplemented("exercise 11.2 (Grid::walk) is not done yet: see book §11.3");
    // @end
}
// @book-end

}  // namespace rt
