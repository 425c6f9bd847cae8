#pragma once
// A wide BVH: the binary SAH tree of core/bvh.hpp collapsed so that each node holds the
// boxes of up to W children side by side (book §10.5), as Embree and tinybvh lay out theirs.
// One node visit tests W boxes with one instruction per plane, and the tree is about log2(W)
// times shallower than the binary one.
//
// The boxes are tested in float, W lanes at once, but conservatively: every rounding of the
// test is pushed outwards (WideRay below), so a box the ray meets in exact arithmetic is
// always entered, and its entry distance is never overestimated. The leaves then decide in
// Real, as brute force does, so the hits found are exactly brute force's.
#include "core/bvh.hpp"

#include <immintrin.h>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace rt {

template <int W>
struct alignas(64) WideNode {
    float lo[3][W];  // lo[axis][child]; an empty child slot has an empty box (lo > hi)
    float hi[3][W];
    std::uint32_t first[W];  // an inner child: its node; a leaf child: its first item slot (or
                             // whatever the owner renumbered it to: see MeshAccel)
    std::uint32_t count[W];  // a leaf child: its item count (>= 1); an inner child or an empty slot: 0
};

template <int W>
struct WideBvh {
    std::vector<WideNode<W>> nodes;  // nodes[0] is the root; empty for no items
    bool root_is_leaf = false;       // one leaf holds everything (items slots 0..count)
    std::uint32_t root_count = 0;

    std::size_t memory_bytes() const { return nodes.size() * sizeof(WideNode<W>); }
};

// The binary tree collapsed: item slots (bvh.items) are kept, so per-slot data stays valid.
template <int W>
WideBvh<W> collapse(const FlatBvh& bvh);

// A ray prepared for the float box test. Two things make a float test lose a box the exact
// one enters: the origin's rounding to float, and the rounding of each subtraction and
// product. The first is taken care of exactly: the near planes are measured from the origin
// rounded the way that moves them closer, the far planes from the one that moves them away.
// The second is relative (a few float epsilons of the distance), and the entry distance is
// lowered and the exit raised by kSlack of their size, more than all of them together.
template <int W>
struct WideRay {
    float origin_near[3], origin_far[3], inv[3];
    std::uint32_t near_offset[3], far_offset[3];  // where each axis's near and far planes are in a node

    static constexpr float kSlack = 0x1p-20f;  // 16 float epsilons

    explicit WideRay(const Ray& ray) : WideRay(ray, Real(1) / ray.direction) {}

    // inv_direction: 1 / ray.direction, when the caller has it already.
    WideRay(const Ray& ray, const Vec3& inv_direction) {
        for (int a = 0; a < 3; ++a) {
            const bool near_hi = inv_direction[a] < 0;  // the near plane is the box's hi side
            inv[a] = float(inv_direction[a]);           // +-0 directions give +-inf, whose sign is kept
            const float below = float_below(ray.origin[a]), above = float_above(ray.origin[a]);
            origin_near[a] = near_hi ? below : above;
            origin_far[a] = near_hi ? above : below;
            const auto lo = std::uint32_t(offsetof(WideNode<W>, lo) + a * sizeof(float[W]));
            const auto hi = std::uint32_t(offsetof(WideNode<W>, hi) + a * sizeof(float[W]));
            near_offset[a] = near_hi ? hi : lo;
            far_offset[a] = near_hi ? lo : hi;
        }
    }
};

// W floats as one vector of the compiler's (GCC's and Clang's vector_size). Spelled out per
// width: GCC's link-time optimiser cannot stream a vector size that depends on W.
template <int W>
struct FloatLanes;
template <>
struct FloatLanes<4> {
    using type = float __attribute__((vector_size(16)));
};
template <>
struct FloatLanes<8> {
    using type = float __attribute__((vector_size(32)));
};

// Bit c set where lane c of a comparison's result is true.
inline unsigned lane_mask(FloatLanes<4>::type m) {
    return unsigned(_mm_movemask_ps(__m128(m)));
}
inline unsigned lane_mask(FloatLanes<8>::type m) {
#ifdef __AVX__
    return unsigned(_mm256_movemask_ps(__m256(m)));
#else
    FloatLanes<4>::type half[2];
    std::memcpy(half, &m, sizeof half);
    return lane_mask(half[0]) | lane_mask(half[1]) << 4;
#endif
}

// Where the ray enters each child's box within [tmin, tmax] (float bounds, already rounded
// outwards), lowered to be safe, in t; returns which children it enters (bit c for child c).
//
// kAhead: tmin >= 0, the usual case, and a cheaper one. Every distance that can decide the
// answer is then >= 0 and computed to a few float epsilons *relative*, so only the exit
// needs raising before the comparison (one multiply-add on the path from the node's
// load to the next node's), and the entry is lowered for the caller off that path. A
// distance that comes out negative is one whose exact value is negative too (rounding keeps
// signs), so it can only lose to tmin.
template <bool kAhead, int W>
inline unsigned enter(const WideNode<W>& node, const WideRay<W>& ray, float tmin, float tmax, float (&t)[W]) {
    using F = typename FloatLanes<W>::type;
    F near[3], far[3];
    const char* base = reinterpret_cast<const char*>(&node);
    for (int a = 0; a < 3; ++a) {
        F n, f;
        std::memcpy(&n, base + ray.near_offset[a], sizeof n);
        std::memcpy(&f, base + ray.far_offset[a], sizeof f);
        near[a] = (n - ray.origin_near[a]) * ray.inv[a];
        far[a] = (f - ray.origin_far[a]) * ray.inv[a];
    }
    // The largest entry and smallest exit, as a tree (shorter than a chain). A NaN (0 * inf:
    // the ray lies in a slab's plane) makes `x > y ? x : y` give y: in the inner pair, at
    // worst the other distance is dropped (the interval only grows); the outer pair has the
    // bound that is never NaN second, so the NaN goes no further.
    const F tmin_v = F{} + tmin, tmax_v = F{} + tmax;
    const F lo_x = near[0] > tmin_v ? near[0] : tmin_v, lo_yz = near[1] > near[2] ? near[1] : near[2];
    const F hi_x = far[0] < tmax_v ? far[0] : tmax_v, hi_yz = far[1] < far[2] ? far[1] : far[2];
    F lo = lo_yz > lo_x ? lo_yz : lo_x;
    F hi = hi_yz < hi_x ? hi_yz : hi_x;
    // The tiny absolute term covers products that underflowed to denormals.
    constexpr float tiny = std::numeric_limits<float>::min();
    if constexpr (kAhead) {
        const unsigned mask = lane_mask(F(lo <= hi * (1 + WideRay<W>::kSlack) + tiny));
        lo *= 1 - WideRay<W>::kSlack;
        std::memcpy(t, &lo, sizeof t);
        return mask;
    } else {
        const F abs_lo = lo < 0 ? -lo : lo, abs_hi = hi < 0 ? -hi : hi;
        lo -= abs_lo * WideRay<W>::kSlack;
        hi += abs_hi * WideRay<W>::kSlack + tiny;
        std::memcpy(t, &lo, sizeof t);
        return lane_mask(F(lo <= hi));
    }
}

// Both queries walk the tree the same way: the children a ray enters, one followed and the
// others on a stack with their entry distances. A leaf is tested whole, leaf(first, count,
// interval): the caller keeps its items together (geometry/triangle_block.hpp). As soon as
// a child is known to be entered its memory is asked for: a node here, a leaf through
// fetch(first), so that it is on its way while the search goes on elsewhere (on a big mesh
// each visit can be a trip to memory).
// - The closest hit (kAny false), as closest_hit() in core/bvh.hpp: nearest child first;
//   leaf narrows interval.max and returns true when it finds a closer hit, and a postponed
//   child whose entry lies beyond the best hit found since is skipped.
// - Any hit (kAny true): the first leaf that returns true ends the search. Children go in
//   slot order: sorting them measured slower than the blockers it finds sooner.
// kAhead: interval.min >= 0, which lets enter() take its cheaper form.
template <bool kAny, bool kAhead, int W, class Leaf, class Fetch>
bool traverse_from(const WideBvh<W>& bvh, const WideRay<W>& r, Interval interval, Leaf&& leaf, Fetch&& fetch) {
    if (bvh.nodes.empty() && !bvh.root_is_leaf) return false;
    TallyScope tally;
    TraversalCount& count = tally.count;
    if (bvh.root_is_leaf) {
        count.items += bvh.root_count;
        return leaf(0, bvh.root_count, interval);
    }
    const float tmin = float_below(interval.min);  // >= 0 when interval.min is
    float tmax = float_above(widen_far(interval.max));
    struct Entry {
        std::uint32_t first, count;
        float t;
    };
    Entry stack[(W - 1) * kMaxBvhDepth + 2];
    int top = 0;
    Entry at{0, 0, tmin};
    bool found = false;
    for (;;) {
        if (at.count != 0) {
            count.items += at.count;
            if (leaf(at.first, at.count, interval)) {
                if (kAny) return true;
                found = true;
                tmax = float_above(widen_far(interval.max));
            }
        } else {
            const WideNode<W>& node = bvh.nodes[at.first];
            float t[W];
            unsigned mask = enter<kAhead>(node, r, tmin, tmax, t);
            count.nodes += W;
            for (unsigned m = mask; m != 0; m &= m - 1) {
                const int c = std::countr_zero(m);
                if (node.count[c] == 0) {
                    const char* p = reinterpret_cast<const char*>(&bvh.nodes[node.first[c]]);
                    for (int line = 0; line < int(sizeof(WideNode<W>)); line += 64) __builtin_prefetch(p + line);
                } else {
                    fetch(node.first[c]);
                }
            }
            if (mask != 0) {
                if (kAny || (mask & (mask - 1)) == 0) {  // slot order: the first followed, the rest pushed
                    int c = std::countr_zero(mask);
                    at = Entry{node.first[c], node.count[c], t[c]};
                    for (mask &= mask - 1; mask != 0; mask &= mask - 1) {
                        c = std::countr_zero(mask);
                        stack[top++] = Entry{node.first[c], node.count[c], t[c]};
                    }
                    continue;
                }
                if (std::popcount(mask) == 2) {  // the commonest case after one: no sort
                    int c0 = std::countr_zero(mask), c1 = std::countr_zero(mask & (mask - 1));
                    if (t[c1] < t[c0]) std::swap(c0, c1);
                    stack[top++] = Entry{node.first[c1], node.count[c1], t[c1]};
                    at = Entry{node.first[c0], node.count[c0], t[c0]};
                    continue;
                }
                // Nearest first (insertion sort: there are few), all but the nearest pushed.
                int order[W], n = 0;
                for (; mask != 0; mask &= mask - 1) {
                    const int c = std::countr_zero(mask);
                    int j = n++;
                    for (; j > 0 && t[order[j - 1]] > t[c]; --j) order[j] = order[j - 1];
                    order[j] = c;
                }
                for (int i = n - 1; i > 0; --i) {
                    const int c = order[i];
                    stack[top++] = Entry{node.first[c], node.count[c], t[c]};
                }
                at = Entry{node.first[order[0]], node.count[order[0]], t[order[0]]};
                continue;
            }
        }
        // Next: the nearest postponed child still in front of the best hit.
        for (;;) {
            if (top == 0) return found;
            at = stack[--top];
            if (kAny || at.t <= tmax) break;
        }
    }
}

template <bool kAny, int W, class Leaf, class Fetch>
bool traverse(const WideBvh<W>& bvh, const WideRay<W>& ray, Interval interval, Leaf&& leaf, Fetch&& fetch) {
    return interval.min >= 0 ? traverse_from<kAny, true>(bvh, ray, interval, leaf, fetch)
                             : traverse_from<kAny, false>(bvh, ray, interval, leaf, fetch);
}

template <int W, class Leaf, class Fetch>
bool closest_hit(const WideBvh<W>& bvh, const WideRay<W>& ray, Interval interval, Leaf&& leaf, Fetch&& fetch) {
    return traverse<false>(bvh, ray, interval, leaf, fetch);
}

template <int W, class Leaf, class Fetch>
bool any_hit(const WideBvh<W>& bvh, const WideRay<W>& ray, Interval interval, Leaf&& leaf, Fetch&& fetch) {
    return traverse<true>(bvh, ray, interval, leaf, fetch);
}

}  // namespace rt
