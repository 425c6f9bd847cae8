// Chapter 10 exercises: bounding boxes and the bounding volume hierarchy (book §10, course
// §9.9.1-9.9.2). Declared in common/accel/course_bvh.hpp.
#include "accel/course_bvh.hpp"
#include "core/exercise.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

// @book slab
bool hit_box(const Box& box, const Ray& ray, Interval interval) {
    // @exercise 10.1 | hit_box | book §10.1
    Real t0 = interval.min, t1 = interval.max;
    for (int axis = 0; axis < 3; ++axis) {
        // Test the sign of 1/d, not of d: for d = -0 it is -inf, so the slab's planes swap
        // as they must, where "d >= 0" would say +0 and -0 alike.
        const Real a = Real(1) / ray.direction[axis];
        Real near = (box.min[axis] - ray.origin[axis]) * a;
        Real far = (box.max[axis] - ray.origin[axis]) * a;
        if (a < 0) std::swap(near, far);
        // Written so that a NaN (0 * inf: the ray lies in this slab's plane) keeps the
        // interval as it was instead of rejecting.
        if (near > t0) t0 = near;
        if (far < t1) t1 = far;
    }
    // Each t above is rounded; without a little slack at the far end a ray through a box's
    // edge could miss a box that holds its hit.
    return t0 <= t1 + std::abs(t1) * (4 * std::numeric_limits<Real>::epsilon());
    // @end
}
// @book-end

// @book sorted
BvhRef build_sorted(BvhBuilder& builder, std::span<std::uint32_t> primitives, int axis) {
    // @exercise 10.2 | build_sorted | book §10.3
    if (primitives.size() == 1) return builder.primitive(primitives[0]);
    std::sort(primitives.begin(), primitives.end(),
              [&](std::uint32_t i, std::uint32_t j) { return builder.centre(i)[axis] < builder.centre(j)[axis]; });
    const std::size_t half = primitives.size() / 2;
    const int next = (axis + 1) % 3;
    const BvhRef left = build_sorted(builder, primitives.first(half), next);
    const BvhRef right = build_sorted(builder, primitives.subspan(half), next);
    return builder.add_node(left, right);
    // @end
}
// @book-end

// @book midpoint
BvhRef build_midpoint(BvhBuilder& builder, std::span<std::uint32_t> primitives, int axis) {
    // @exercise 10.3 | build_midpoint | book §10.3
    if (primitives.size() == 1) return builder.primitive(primitives[0]);
    Box box;
    for (std::uint32_t p : primitives) box.expand(builder.box(builder.primitive(p)));
    const Real middle = (box.min[axis] + box.max[axis]) / 2;
    const auto split = std::partition(primitives.begin(), primitives.end(),
                                      [&](std::uint32_t p) { return builder.centre(p)[axis] < middle; });
    auto left_count = std::size_t(split - primitives.begin());
    // Every centre on one side (the course's pseudo-code would recurse forever): halve.
    if (left_count == 0 || left_count == primitives.size()) left_count = primitives.size() / 2;
    const int next = (axis + 1) % 3;
    const BvhRef left = build_midpoint(builder, primitives.first(left_count), next);
    const BvhRef right = build_midpoint(builder, primitives.subspan(left_count), next);
    return builder.add_node(left, right);
    // @end
}
// @book-end

// @book traversal
bool Bvh::hit_node(const SurfaceList& surfaces, BvhRef ref, const Ray& ray, Interval interval, HitRecord& best) const {
    // @exercise 10.4 | Bvh::hit_node | book §10.4
    if (is_primitive(ref)) return hit_primitive(surfaces, ref, ray, interval, best);
    const CourseBvhNode& n = node(ref);
    if (!hit_box(n.box, ray, interval)) return false;
    const bool left = hit_node(surfaces, n.left, ray, interval, best);
    // A hit on the left limits the right: only something closer can matter there.
    if (left) interval.max = best.t;
    const bool right = hit_node(surfaces, n.right, ray, interval, best);
    return left || right;
    // @end
}
// @book-end

}  // namespace rt
