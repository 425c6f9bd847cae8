// Chapter 12 exercises: the binary space partitioning tree (book §12, course §9.9.4).
// Declared in common/accel/bsp.hpp.
#include "accel/bsp.hpp"
#include "core/exercise.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

// @book four-cases
bool Bsp::hit_node(const SurfaceList& surfaces, BspRef ref, const Ray& ray, Interval interval, HitRecord& best) const {
    // @exercise 12.1 | Bsp::hit_node | book §12.2
    const BspNode& n = node(ref);
    if (n.leaf()) return hit_leaf(surfaces, n, ray, interval, best);
    const Real d = ray.direction[n.axis];
    const Real p = ray.origin[n.axis] + interval.min * d;  // where this part of the ray starts
    // The side the part starts on is searched first. On the plane itself, the side the ray
    // moves to.
    const bool starts_below = p < n.split || (p == n.split && d < 0);
    const BspRef near = starts_below ? n.left : n.right;
    const BspRef far = starts_below ? n.right : n.left;
    // Cases 1 and 3: moving away from the plane, or along it (d = +0 or -0), the ray never
    // reaches the far side. Written as "not towards" so that -0 lands here, not below.
    if (starts_below ? !(d > 0) : !(d < 0)) return hit_node(surfaces, near, ray, interval, best);
    // Cases 2 and 4: the near side up to the plane, then, if nothing was hit, the far side.
    // Both parts reach `s` past the plane: a hit computed a rounding error on the wrong
    // side of it is still found (book §12.3).
    const Real t = (n.split - ray.origin[n.axis]) / d;
    const Real s = slack(ray, n.axis);
    if (t - s > interval.max) return hit_node(surfaces, near, ray, interval, best);  // the part ends first
    if (hit_node(surfaces, near, ray, Interval{interval.min, std::min(interval.max, t + s)}, best)) return true;
    return hit_node(surfaces, far, ray, Interval{std::max(interval.min, t - s), interval.max}, best);
    // @end
}
// @book-end

// @book midpoint
BspRef build_midpoint(BspBuilder& builder, std::span<const std::uint32_t> items, const Box& cell, int depth) {
    // @exercise 12.2 | build_midpoint | book §12.4
    if (items.size() <= builder.leaf_size() || depth >= builder.max_depth()) return builder.add_leaf(items);
    std::vector<std::uint32_t> below, above;
    // The axis of this depth first; if its middle sends more than half the items to both
    // sides, the cut costs more in copies than it saves, so the next axis; then a leaf.
    for (int k = 0; k < 3; ++k) {
        const int axis = (depth + k) % 3;
        const Real split = (cell.min[axis] + cell.max[axis]) / 2;
        builder.sort(items, axis, split, below, above);
        if (2 * (below.size() + above.size()) > 3 * items.size()) continue;
        // Children first (their nodes come before this one), in order: one after the other,
        // so the tree is the same whatever the compiler.
        const BspRef left = build_midpoint(builder, below, below_plane(cell, axis, split), depth + 1);
        const BspRef right = build_midpoint(builder, above, above_plane(cell, axis, split), depth + 1);
        return builder.add_inner(axis, split, left, right);
    }
    return builder.add_leaf(items);
    // @end
}
// @book-end

}  // namespace rt
