#include "accel/grid.hpp"

#include "core/hit_rounding.hpp"
#include "core/limits.hpp"
#include "core/traversal_count.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rt {

Grid::Grid(const SurfaceList& surfaces, Real density) : primitives_(primitives_of(surfaces)) {
    std::vector<Box> boxes;
    boxes.reserve(primitives_.size());
    for (const Primitive& p : primitives_) {
        boxes.push_back(rt::bounding_box(surfaces, p));
        bounds_.expand(boxes.back());
    }
    if (primitives_.empty()) {
        first_.assign(2, 0);
        return;
    }
    // Cells about as long as wide, about `density` of them per primitive. An axis the scene
    // is flat along still gets a thickness (a thousandth of the longest side), and at least
    // one step of the numbers each way: far from the origin the thickness can be below
    // their step (float at 2e6: 0.25), and a box of no thickness has cells of no volume.
    const Vec3 extent = bounds_.max - bounds_.min;
    const Real longest = std::max(extent.x, std::max(extent.y, extent.z));
    const Real floor_side = longest > 0 ? longest * Real(1e-3) : Real(1);
    for (int a = 0; a < 3; ++a)
        if (extent[a] < floor_side) {
            const Real lo = bounds_.min[a] - (floor_side - extent[a]) / 2;
            const Real hi = bounds_.max[a] + (floor_side - extent[a]) / 2;
            bounds_.min[a] = std::min(lo, std::nextafter(bounds_.min[a], -kInfinity));
            bounds_.max[a] = std::max(hi, std::nextafter(bounds_.max[a], kInfinity));
        }
    const Vec3 e = bounds_.max - bounds_.min;
    const double k =
        std::cbrt(double(density) * double(primitives_.size()) / (double(e.x) * double(e.y) * double(e.z)));
    for (int a = 0; a < 3; ++a) {
        n_[a] = int(std::clamp(std::round(double(e[a]) * k), 1.0, 256.0));
        cell_size_[a] = e[a] / Real(n_[a]);
    }
    // The pad: a ten-thousandth of a cell, and never less than the rounding in where a hit is
    // computed, which grows with the coordinates (core/hit_rounding.hpp): far from the origin, in
    // float, that decides (at 1e6: 2 units of 1/16).
    const Real rounding = hit_rounding(bounds_);
    pad_ = std::max(Real(1e-4) * std::min(cell_size_.x, std::min(cell_size_.y, cell_size_.z)), rounding);

    // Every primitive goes into every cell its box (grown by twice the pad) overlaps: two
    // passes, counting and then filling, so the lists sit in one array.
    const auto cell_range = [&](const Box& b, std::array<int, 3>& lo, std::array<int, 3>& hi) {
        for (int a = 0; a < 3; ++a) {
            const auto at = [&](Real x) {
                return int(std::clamp(std::floor((x - bounds_.min[a]) / cell_size_[a]), Real(0), Real(n_[a] - 1)));
            };
            lo[a] = at(b.min[a] - 2 * pad_);
            hi[a] = at(b.max[a] + 2 * pad_);
        }
    };
    std::vector<std::uint32_t> count(cell_count() + 1, 0);
    std::size_t total = 0;
    std::array<int, 3> lo{}, hi{}, c{};
    for (const Box& b : boxes) {
        cell_range(b, lo, hi);
        total += std::size_t(hi[0] - lo[0] + 1) * std::size_t(hi[1] - lo[1] + 1) * std::size_t(hi[2] - lo[2] + 1);
        if (!limits::contains(limits::grid_entries, double(total)))  // stops counting there: bounded work
            throw std::invalid_argument("grid: its primitives overlap too many cells (" +
                                        std::string(limits::grid_entries.name) + " " +
                                        limits::describe(limits::grid_entries) + "); use a BVH (--accel fast)");
        for (c[2] = lo[2]; c[2] <= hi[2]; ++c[2])
            for (c[1] = lo[1]; c[1] <= hi[1]; ++c[1])
                for (c[0] = lo[0]; c[0] <= hi[0]; ++c[0]) ++count[index(c) + 1];
    }
    first_.assign(cell_count() + 1, 0);
    for (std::size_t i = 1; i < first_.size(); ++i) first_[i] = first_[i - 1] + count[i];
    items_.resize(total);
    std::vector<std::uint32_t> fill(first_.begin(), first_.end() - 1);
    for (std::uint32_t p = 0; p < boxes.size(); ++p) {
        cell_range(boxes[p], lo, hi);
        for (c[2] = lo[2]; c[2] <= hi[2]; ++c[2])
            for (c[1] = lo[1]; c[1] <= hi[1]; ++c[1])
                for (c[0] = lo[0]; c[0] <= hi[0]; ++c[0]) items_[fill[index(c)]++] = p;
    }
}

bool Grid::clip(const Ray& ray, Interval& interval) const {
    if (bounds_.empty()) return false;
    if (clip_to_box(bounds_, ray, interval)) return true;
    // A ray that misses the box by a rounding error may still hit a wall lying in its face:
    // that hit is computed a rounding error in or out, and far from the origin that error is
    // a unit in the last place of the coordinates. Such a ray is clipped to the box grown by
    // the rounding; start() clamps its entry point into the nearest cell.
    return clip_to_box(grown_by_rounding(bounds_), ray, interval);
}

Real Grid::cell_exit(const Ray& ray, const GridWalk& walk) const {
    const Real t = std::min(walk.t_max.x, std::min(walk.t_max.y, walk.t_max.z));
    return t + pad_ / glm::length(ray.direction);
}

bool Grid::next(const Ray& ray, GridWalk& walk) const {
    const int a =
        walk.t_max.x <= walk.t_max.y ? (walk.t_max.x <= walk.t_max.z ? 0 : 2) : (walk.t_max.y <= walk.t_max.z ? 1 : 2);
    if (!(walk.t_max[a] <= walk.t_end)) return false;  // the next cell starts past the end
    walk.cell[a] += walk.step[a];
    if (walk.cell[a] < 0 || walk.cell[a] >= n_[a]) return false;
    // From the plane itself, not by adding up steps: no error accumulates along the walk.
    walk.t_max[a] = (boundary(a, walk.cell[a] + (walk.step[a] > 0)) - ray.origin[a]) / ray.direction[a];
    return true;
}

bool Grid::hit_cell(const SurfaceList& surfaces, const GridWalk& walk, const Ray& ray, Interval interval,
                    HitRecord& best) const {
    const std::size_t c = index(walk.cell);
    ++traversal_tally.nodes;  // cells visited
    bool found = false;
    for (std::uint32_t k = first_[c]; k < first_[c + 1]; ++k) {
        ++traversal_tally.items;
        if (hit_closer(surfaces, primitives_[items_[k]], ray, Interval{interval.min, std::min(interval.max, best.t)},
                       best))
            found = true;
    }
    return found;
}

bool Grid::hit(const SurfaceList& surfaces, const Ray& ray, Interval interval, HitRecord& rec) const {
    HitRecord best = no_hit_before(interval.max);
    if (!walk(surfaces, ray, interval, best)) return false;
    rec = best;
    return true;
}

bool Grid::walk_unchecked(const SurfaceList& surfaces, const Ray& ray, Interval interval, HitRecord& best) const {
    GridWalk w;
    if (!start(ray, interval, w)) return false;
    do {
        if (hit_cell(surfaces, w, ray, Interval{interval.min, best.t}, best)) return true;
    } while (next(ray, w));
    return false;
}

bool Grid::occluded(const SurfaceList& surfaces, const Ray& ray, Interval interval) const {
    // Any hit in the interval will do, wherever it lies: no cell check needed.
    GridWalk w;
    if (!start(ray, interval, w)) return false;
    do {
        const std::size_t c = index(w.cell);
        ++traversal_tally.nodes;
        for (std::uint32_t k = first_[c]; k < first_[c + 1]; ++k) {
            ++traversal_tally.items;
            if (rt::occluded(surfaces, primitives_[items_[k]], ray, interval)) return true;
        }
    } while (next(ray, w));
    return false;
}

}  // namespace rt
