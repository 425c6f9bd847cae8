#pragma once
// A 4-wide BVH: the binary SAH tree of core/bvh.hpp collapsed so that each node holds the
// boxes of up to four children side by side (book §10.5). One node visit tests four boxes,
// and the tests are the same arithmetic on four lanes, which the compiler turns into SIMD
// instructions; the tree is about half as deep as the binary one, and a node's four boxes
// sit in 96 consecutive bytes. Each lane's test is exactly enter() of core/bvh.hpp, so the boxes a
// ray enters, and so the hits it finds, are the binary tree's.
#include "core/bvh.hpp"

#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

namespace rt {

struct alignas(64) Bvh4Node {
    float lo[3][4];  // lo[axis][child]; an empty child slot has an empty box (lo > hi)
    float hi[3][4];
    std::uint32_t first[4];  // an inner child: its node; a leaf child: its first item slot
    std::uint32_t count[4];  // a leaf child: its item count (>= 1); an inner child or an empty slot: 0
};

struct Bvh4 {
    std::vector<Bvh4Node> nodes;  // nodes[0] is the root; empty for no items
    bool root_is_leaf = false;    // one leaf holds everything (items slots 0..count)
    std::uint32_t root_count = 0;

    std::size_t memory_bytes() const { return nodes.size() * sizeof(Bvh4Node); }
};

// The binary tree collapsed: item slots (bvh.items) are kept, so per-slot data stays valid.
Bvh4 collapse(const FlatBvh& bvh);

// A ray prepared for the 4-wide test: which of lo and hi is the near plane along each axis,
// chosen once by the sign of 1/d (as in enter()).
struct Bvh4Ray {
    Vec3 origin;
    Vec3 inv;
    int near_hi[3];

    explicit Bvh4Ray(const Ray& ray) : origin(ray.origin), inv(Real(1) / ray.direction) {
        for (int a = 0; a < 3; ++a) near_hi[a] = inv[a] < 0;
    }
};

// Where the ray enters each child's box within [tmin, tmax]; +inf for a miss. Each lane is
// enter()'s arithmetic, in the same order; written with the compiler's vector types (GCC's
// and Clang's vector_size), so the four lanes are one instruction each where the machine
// has the registers (AVX: four doubles) and two where it has half (SSE2).
inline void enter4(const Bvh4Node& node, const Bvh4Ray& ray, Real tmin, Real tmax, Real (&t)[4]) {
    using V = Real __attribute__((vector_size(4 * sizeof(Real))));
    using F = float __attribute__((vector_size(16)));
    V lo = V{} + tmin, hi = V{} + tmax;
    for (int a = 0; a < 3; ++a) {
        F n, f;
        std::memcpy(&n, ray.near_hi[a] ? node.hi[a] : node.lo[a], sizeof n);
        std::memcpy(&f, ray.near_hi[a] ? node.lo[a] : node.hi[a], sizeof f);
        const V o = V{} + ray.origin[a], inv = V{} + ray.inv[a];
        const V near = (__builtin_convertvector(n, V) - o) * inv;
        const V far = (__builtin_convertvector(f, V) - o) * inv;
        lo = near > lo ? near : lo;  // a NaN (0 * inf) keeps the bound, as in enter()
        hi = far < hi ? far : hi;
    }
    const V magnitude = hi < 0 ? -hi : hi;
    const V reach = hi + magnitude * (4 * std::numeric_limits<Real>::epsilon());  // widen_far
    const V entered = lo <= reach ? lo : V{} + kInfinity;
    std::memcpy(t, &entered, sizeof t);
}

// The closest hit, as closest_hit() in core/bvh.hpp: children entered nearest first, the
// others on a stack with their entry distances, skipped when popped if a hit closer than
// that has been found since. leaf(k, interval) as there.
template <class Leaf>
bool closest_hit(const Bvh4& bvh, const Ray& ray, Interval interval, Leaf&& leaf) {
    if (bvh.nodes.empty() && !bvh.root_is_leaf) return false;
    TallyScope tally;
    TraversalCount& count = tally.count;
    bool found = false;
    if (bvh.root_is_leaf) {
        count.items += bvh.root_count;
        for (std::uint32_t k = 0; k < bvh.root_count; ++k)
            if (leaf(k, interval)) found = true;
        return found;
    }
    const Bvh4Ray r(ray);
    struct Entry {
        std::uint32_t first, count;
        Real t;
    };
    Entry stack[3 * kMaxBvhDepth + 4];
    int top = 0;
    stack[top++] = Entry{0, 0, interval.min};
    while (top > 0) {
        const Entry e = stack[--top];
        if (!(e.t <= widen_far(interval.max))) continue;  // behind the best hit found since
        if (e.count != 0) {
            count.items += e.count;
            for (std::uint32_t k = e.first; k < e.first + e.count; ++k)
                if (leaf(k, interval)) found = true;
            continue;
        }
        const Bvh4Node& node = bvh.nodes[e.first];
        Real t[4];
        enter4(node, r, interval.min, interval.max, t);
        count.nodes += 4;
        // Push the entered children farthest first, so the nearest is popped next.
        int order[4], n = 0;
        for (int c = 0; c < 4; ++c)
            if (t[c] != kInfinity) order[n++] = c;
        for (int i = 1; i < n; ++i)  // at most four: insertion sort, farthest first
            for (int j = i; j > 0 && t[order[j]] > t[order[j - 1]]; --j) std::swap(order[j], order[j - 1]);
        for (int i = 0; i < n; ++i) {
            const int c = order[i];
            stack[top++] = Entry{node.first[c], node.count[c], t[c]};
        }
    }
    return found;
}

// Is there any hit? Stops at the first one leaf(k, interval) reports.
template <class Leaf>
bool any_hit(const Bvh4& bvh, const Ray& ray, Interval interval, Leaf&& leaf) {
    if (bvh.nodes.empty() && !bvh.root_is_leaf) return false;
    TallyScope tally;
    TraversalCount& count = tally.count;
    if (bvh.root_is_leaf) {
        for (std::uint32_t k = 0; k < bvh.root_count; ++k) {
            ++count.items;
            if (leaf(k, interval)) return true;
        }
        return false;
    }
    const Bvh4Ray r(ray);
    std::uint32_t stack[3 * kMaxBvhDepth + 4];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Bvh4Node& node = bvh.nodes[stack[--top]];
        Real t[4];
        enter4(node, r, interval.min, interval.max, t);
        count.nodes += 4;
        for (int c = 0; c < 4; ++c) {
            if (t[c] == kInfinity) continue;
            if (node.count[c] == 0) {
                stack[top++] = node.first[c];
                continue;
            }
            for (std::uint32_t k = node.first[c]; k < node.first[c] + node.count[c]; ++k) {
                ++count.items;
                if (leaf(k, interval)) return true;
            }
        }
    }
    return false;
}

}  // namespace rt
