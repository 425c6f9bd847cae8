#pragma once
// The bounding volume hierarchy as the renderer builds it (book §10.5): flat nodes of 32
// bytes in one array and a surface-area-heuristic build. It knows nothing of what it holds:
// items are numbers. It is searched only once collapsed into the wide tree of
// core/wide_bvh.hpp: meshes over their triangles, and the scene over its surfaces, the two
// levels of the fast path (accel/two_level_bvh.hpp). The course's form, the one students
// build, is accel/course_bvh.hpp.
#include "core/box.hpp"

#include <cstdint>
#include <span>
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

// Deeper trees are cut to median splits while building, so no leaf lies deeper than this:
// what bounds the stack of the search (core/wide_bvh.hpp; collapsing never deepens a tree).
inline constexpr int kMaxBvhDepth = 60;

// A ray prepared for many box tests: 1/d once per ray. A direction component of +0 or -0
// gives +inf or -inf, whose sign still says which slab plane comes first (course §9.9.1).
struct BoxRay {
    Vec3 origin;
    Vec3 inv;
    explicit BoxRay(const Ray& ray) : origin(ray.origin), inv(Real(1) / ray.direction) {}
};

// Where the ray enters the node's box within [tmin, tmax], or +inf if it misses (the binary
// tree's node test: bench/bounding_volumes.cpp compares boxes and balls with it). The far
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

}  // namespace rt
