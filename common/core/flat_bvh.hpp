#pragma once
// The bounding volume hierarchy in the form the renderer runs (book §10.5): flat nodes of
// 32 bytes in one array, a surface-area-heuristic build, and loops instead of recursion.
// It knows nothing of what it holds: items are numbers, and the caller's `leaf` function
// tests one. Meshes use it over their triangles, and the scene over its surfaces: the two
// levels of the fast path (accel/two_level_bvh.hpp). The course's form, the one students build,
// is accel/course_bvh.hpp.
#include "core/box.hpp"
#include "core/traversal_count.hpp"

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace rt {

struct BvhNode {
    float lo[3];
    std::uint32_t first;  // inner node: its left child (the right one is first + 1); leaf: its first item
    float hi[3];
    std::uint32_t count;  // how many items the leaf holds; 0 for an inner node

    bool leaf() const { return count != 0; }
};

struct FlatBvh {
    std::vector<BvhNode> nodes;        // nodes[0] is the root; empty for no items
    std::vector<std::uint32_t> items;  // item numbers, leaf after leaf
    int depth = 0;                     // of the deepest leaf; the root is at depth 0

    std::size_t memory_bytes() const { return nodes.size() * sizeof(BvhNode) + items.size() * sizeof(std::uint32_t); }
};

// Builds over the items' boxes (item k has boxes[k]) with a binned surface-area heuristic;
// a leaf holds at most max_leaf items. Boxes are stored in float, rounded outwards, so a
// node never shrinks by the conversion. `lanes` items are tested in one pass (a mesh's
// triangle blocks), so the heuristic counts a leaf's cost in passes: up to `lanes` items
// cost as much as one, as Embree's builders count them.
FlatBvh build_bvh(std::span<const Box> boxes, unsigned max_leaf = 4, unsigned lanes = 1);

// Deeper trees are cut to median splits while building, so a traversal stack of this many
// entries always suffices.
inline constexpr int kMaxBvhDepth = 60;

// A ray prepared for many box tests: 1/d once per ray. A direction component of +0 or -0
// gives +inf or -inf, whose sign still says which slab plane comes first (course §9.9.1).
struct BoxRay {
    Vec3 origin;
    Vec3 inv;
    explicit BoxRay(const Ray& ray) : origin(ray.origin), inv(Real(1) / ray.direction) {}
};

// Where the ray enters the node's box within [tmin, tmax], or +inf if it misses. The far
// distance is padded as in might_hit (core/box.hpp), and a NaN (the ray lies in a slab's
// plane: 0 * inf) leaves that slab's bounds alone.
inline Real enter(const BvhNode& node, const BoxRay& ray, Real tmin, Real tmax) {
    for (int a = 0; a < 3; ++a) {
        // The sign of 1/d, not a comparison of the two distances, says which plane is near:
        // when one distance is NaN, comparing them would pick the wrong one.
        const bool flip = ray.inv[a] < 0;
        const Real near = (Real(flip ? node.hi[a] : node.lo[a]) - ray.origin[a]) * ray.inv[a];
        const Real far = (Real(flip ? node.lo[a] : node.hi[a]) - ray.origin[a]) * ray.inv[a];
        tmin = near > tmin ? near : tmin;
        tmax = far < tmax ? far : tmax;
    }
    return tmin <= widen_far(tmax) ? tmin : kInfinity;
}

// The closest hit: nearer child first, the farther one on a stack with its entry distance,
// skipped when popped if a hit closer than that has been found since. leaf(k, interval)
// tests the item in slot k (item number bvh.items[k]; a caller may keep per-item data in
// slot order) against `interval`; when it finds a hit closer than the best so far it keeps
// it, sets interval.max to its t, and returns true.
template <class Leaf>
bool closest_hit(const FlatBvh& bvh, const Ray& ray, Interval interval, Leaf&& leaf) {
    if (bvh.nodes.empty()) return false;
    TallyScope tally;
    TraversalCount& count = tally.count;
    const BoxRay r(ray);
    const BvhNode* nodes = bvh.nodes.data();
    ++count.nodes;
    if (enter(nodes[0], r, interval.min, interval.max) == kInfinity) return false;
    std::pair<std::uint32_t, Real> stack[kMaxBvhDepth + 1];
    int top = 0;
    std::uint32_t at = 0;
    bool found = false;
    for (;;) {
        const BvhNode& node = nodes[at];
        if (!node.leaf()) {
            std::uint32_t near = node.first, far = node.first + 1;
            Real t_near = enter(nodes[near], r, interval.min, interval.max);
            Real t_far = enter(nodes[far], r, interval.min, interval.max);
            count.nodes += 2;
            if (t_far < t_near) {
                std::swap(near, far);
                std::swap(t_near, t_far);
            }
            if (t_near != kInfinity) {
                if (t_far != kInfinity) stack[top++] = {far, t_far};
                at = near;
                continue;
            }
        } else {
            count.items += node.count;
            for (std::uint32_t k = node.first; k < node.first + node.count; ++k)
                if (leaf(k, interval)) found = true;
        }
        // Next: the nearest postponed node still in front of the best hit.
        for (;;) {
            if (top == 0) return found;
            const auto [next, t] = stack[--top];
            if (t <= widen_far(interval.max)) {
                at = next;
                break;
            }
        }
    }
}

// Is there any hit? Stops at the first one leaf(k, interval) reports; order does not
// matter, so no distances are kept.
template <class Leaf>
bool any_hit(const FlatBvh& bvh, const Ray& ray, Interval interval, Leaf&& leaf) {
    if (bvh.nodes.empty()) return false;
    TallyScope tally;
    TraversalCount& count = tally.count;
    const BoxRay r(ray);
    const BvhNode* nodes = bvh.nodes.data();
    std::uint32_t stack[kMaxBvhDepth + 2];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const BvhNode& node = nodes[stack[--top]];
        ++count.nodes;
        if (enter(node, r, interval.min, interval.max) == kInfinity) continue;
        if (node.leaf()) {
            for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
                ++count.items;
                if (leaf(k, interval)) return true;
            }
        } else {
            stack[top++] = node.first + 1;
            stack[top++] = node.first;
        }
    }
    return false;
}

}  // namespace rt
