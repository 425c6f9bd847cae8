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
    if (!clip(ray, interval)) return false;
    const Vec3 p = ray.at(interval.min);  // where the ray is when the walk begins
    for (int a = 0; a < 3; ++a) {
        // Clamped: rounding may put the entry point a hair outside the grid's box.
        const Real cell = std::floor((p[a] - bounds_.min[a]) / cell_size_[a]);
        walk.cell[a] = int(std::clamp(cell, Real(0), Real(n_[a] - 1)));
        const Real d = ray.direction[a];
        walk.step[a] = d > 0 ? 1 : (d < 0 ? -1 : 0);
        // The next plane is the cell's far side in the direction of travel; a ray parallel
        // to an axis never crosses one.
        walk.t_max[a] = walk.step[a] == 0
                            ? kInfinity
                            : (boundary(a, walk.cell[a] + (walk.step[a] > 0 ? 1 : 0)) - ray.origin[a]) / d;
    }
    walk.t_end = interval.max;
    return true;
    // @end
}
// @book-end

// @book walk
bool Grid::walk(const SurfaceList& surfaces, const Ray& ray, Interval interval, HitRecord& best) const {
    // @exercise 11.2 | Grid::walk | book §11.3
    GridWalk w;
    if (!start(ray, interval, w)) return false;
    do {
        // Only hits before the ray leaves this cell count. A primitive that reaches into
        // later cells may be hit there, behind a closer one in a cell not walked yet (course
        // Figure 9.23): that hit is found again, in its own cell. From the ray's own start,
        // and to the padded exit even in the last cell: a wall in the grid's near or far face
        // is hit a rounding error outside the part of the ray inside the box.
        if (hit_cell(surfaces, w, ray, Interval{interval.min, std::min(best.t, cell_exit(ray, w))}, best)) return true;
    } while (next(ray, w));
    return false;
    // @end
}
// @book-end

}  // namespace rt
