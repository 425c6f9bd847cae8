#pragma once
// The uniform grid (course §9.9.3, book §11): space cut into equal boxes, each listing the
// primitives whose boxes overlap it, searched by walking the cells a ray passes through in
// order (Amanatides & Woo 1987) and stopping in the first cell that holds a hit. Where the
// BVH divides the objects, the grid divides space: one object may sit in many cells.
#include "accel/primitive.hpp"

#include <array>
#include <vector>

namespace rt {

// @book grid-walk
// Where a walk through the grid is: the current cell, the direction of the steps along
// each axis, and where the ray crosses the current cell's next plane along each axis.
struct GridWalk {
    std::array<int, 3> cell{};
    std::array<int, 3> step{};  // +1, -1, or 0 for an axis the ray runs parallel to
    Vec3 t_max{kInfinity};      // the t of the next plane along each axis (infinity: never)
    Real t_end = kInfinity;     // where the ray leaves the grid, or its interval ends
};
// @book-end

class Grid {
public:
    // About `density` cells per primitive, shaped to the scene's box, at most 256 a side.
    explicit Grid(const SurfaceList& surfaces, Real density = 2);

    bool hit(const SurfaceList& surfaces, const Ray& ray, Interval interval, HitRecord& rec) const;
    bool occluded(const SurfaceList& surfaces, const Ray& ray, Interval interval) const;
    Box bounding_box() const { return bounds_; }

    // @book grid-start
    // Exercise 11.1: where a ray's walk starts. Clips the interval to the grid (clip());
    // false if the ray misses it. Otherwise the cell holding the point where the clipped
    // interval starts (its index clamped to the grid: that point may lie on a far face, or a
    // rounding error outside), the steps (0 for a component of +0 or -0), each axis's next
    // plane in the direction of travel (boundary(); infinity for a step of 0), and t_end,
    // the clipped interval's end. The tests demand every one of these values, and only them.
    bool start(const Ray& ray, Interval interval, GridWalk& walk) const;
    // Exercise 11.2: the closest hit, walking the cells in the order the ray meets them
    // (start(), next()) and stopping in the first cell that yields one. Each cell is searched
    // (hit_cell()) from the interval's own start, not the clipped one, up to its padded exit
    // (cell_exit()), in the last cell too: a wall lying in the grid's near or far face can be
    // hit a rounding error outside the clipped interval. best.t starts at the interval's end,
    // so no other cap is needed. The tests demand brute force's hit (t, surface, triangle)
    // and the cells visited (traversal_tally.nodes, counted by hit_cell()): each from the
    // first to the one that yields the hit, once.
    bool walk(const SurfaceList& surfaces, const Ray& ray, Interval interval, HitRecord& best) const;

    // Steps the walk into the next cell the ray meets: along the axis whose plane comes
    // first. False when the ray leaves the grid or its interval ends before that cell.
    bool next(const Ray& ray, GridWalk& walk) const;
    // Shrinks the interval to where the ray is inside the grid's box; false if it is empty.
    // A ray that misses the box by no more than the rounding in a hit's coordinates is
    // clipped to the box grown by that much.
    bool clip(const Ray& ray, Interval& interval) const;
    // The coordinate of plane k (0..resolution) along an axis: min + k * cell size, and the
    // box's own face exactly for the last (min + n * (size / n) may round to a hair inside it,
    // and a ray that grazes a wall lying in that face would leave the grid before meeting it).
    Real boundary(int axis, int k) const {
        return k == n_[axis] ? bounds_.max[axis] : bounds_.min[axis] + Real(k) * cell_size_[axis];
    }
    // @book-end
    // Where the ray leaves the walk's current cell, padded a little (book §11.3): a hit
    // there belongs to this cell, since every primitive near a plane sits on both sides.
    Real cell_exit(const Ray& ray, const GridWalk& walk) const;
    // Tests the primitives of the walk's current cell, keeping a closer hit in best.
    bool hit_cell(const SurfaceList& surfaces, const GridWalk& walk, const Ray& ray, Interval interval,
                  HitRecord& best) const;
    // The walk without the cell check of exercise 11.2 (a hit anywhere ends it): wrong, for
    // the test and the book that show why the check is needed (course Figure 9.23).
    bool walk_unchecked(const SurfaceList& surfaces, const Ray& ray, Interval interval, HitRecord& best) const;

    const std::array<int, 3>& resolution() const { return n_; }
    const Vec3& cell_size() const { return cell_size_; }
    std::size_t cell_count() const { return std::size_t(n_[0]) * std::size_t(n_[1]) * std::size_t(n_[2]); }
    std::size_t primitive_count() const { return primitives_.size(); }
    std::size_t entries() const { return items_.size(); }  // primitives listed, summed over cells
    std::size_t memory_bytes() const {
        return first_.size() * sizeof(std::uint32_t) + items_.size() * sizeof(std::uint32_t) +
               primitives_.size() * sizeof(Primitive);
    }

private:
    std::size_t index(const std::array<int, 3>& c) const {
        return (std::size_t(c[2]) * std::size_t(n_[1]) + std::size_t(c[1])) * std::size_t(n_[0]) + std::size_t(c[0]);
    }

    // @book grid-members
    // What start() reads besides boundary(): the grid's box, its cells along each axis, and
    // the size of one cell.
    std::vector<Primitive> primitives_;
    Box bounds_;
    std::array<int, 3> n_{1, 1, 1};
    Vec3 cell_size_{1};
    // @book-end
    Real pad_ = 0;                      // in space: how far past a plane a cell's primitives reach
    std::vector<std::uint32_t> first_;  // cell c lists items_[first_[c] .. first_[c + 1])
    std::vector<std::uint32_t> items_;  // primitive numbers
};

}  // namespace rt
