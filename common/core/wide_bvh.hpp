#pragma once
// A wide BVH: the binary SAH tree of core/flat_bvh.hpp collapsed so that each node holds the
// boxes of up to W children side by side (book §10.5), as Embree and tinybvh lay out theirs.
// One node visit tests W boxes with one instruction per plane, and the tree is about log2(W)
// times shallower than the binary one.
//
// The boxes are tested in float, W lanes at once, but conservatively: every rounding of the
// test is pushed outwards (WideRay below), so a box the ray meets in exact arithmetic is
// always entered, and its entry distance is never overestimated. The leaves then decide in
// Real, as brute force does, so the hits found are exactly brute force's.
#include "core/flat_bvh.hpp"
#include "core/float_round.hpp"
#include "core/search_memory.hpp"
#include "core/traversal_count.hpp"
#include "core/wide_lanes.hpp"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

namespace rt {

// A child slot's reference: an inner child's node number, or a leaf with its item count and
// first item slot, in one word, so that pushing children is one vector store.
inline constexpr std::uint32_t kLeafRef = 1u << 31;
inline constexpr int kLeafCountShift = 27;
inline constexpr std::uint32_t kMaxLeafFirst = (1u << kLeafCountShift) - 1, kMaxLeafCount = 15;
inline std::uint32_t leaf_ref(std::uint32_t first, std::uint32_t count) {
    return kLeafRef | count << kLeafCountShift | first;
}
inline bool is_leaf(std::uint32_t ref) {
    return (ref & kLeafRef) != 0;
}
inline std::uint32_t leaf_first(std::uint32_t ref) {
    return ref & kMaxLeafFirst;
}
inline std::uint32_t leaf_count(std::uint32_t ref) {
    return (ref & ~kLeafRef) >> kLeafCountShift;
}

template <int W>
struct alignas(64) WideNode {
    float lo[3][W];  // lo[axis][child]; an empty child slot has an empty box (lo > hi)
    float hi[3][W];
    std::uint32_t child[W];  // each slot's reference (leaf_ref for a leaf); 0 for an empty slot
    // The slots near to far for each of the eight direction octants, so that a search can
    // push the children it enters in a good order without sorting them: the slot a ray of
    // octant o meets p-th is order[p] >> 3 o & 7 (by box centre along the octant's diagonal).
    // Empty slots come last.
    std::uint32_t order[W];
};

template <int W>
struct WideBvh {
    std::vector<WideNode<W>, SearchAllocator<WideNode<W>>> nodes;  // nodes[0] is the root; empty for no items
    bool root_is_leaf = false;                                     // one leaf holds everything (items slots 0..count)
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
    // The direction's octant: bit a set where it points down axis a, so that the box's hi side
    // is the near one. WideNode::order is indexed by it, and the search is compiled once for
    // each (traverse), so that where each plane sits in a node is a constant.
    unsigned octant = 0;

    static constexpr float kSlack = 0x1p-20f;  // 16 float epsilons

    explicit WideRay(const Ray& ray) : WideRay(ray, Real(1) / ray.direction) {}

    // inv_direction: 1 / ray.direction, when the caller has it already.
    WideRay(const Ray& ray, const Vec3& inv_direction) {
        float below[3], above[3];
        float_bounds(ray.origin, below, above);
        for (int a = 0; a < 3; ++a) {
            const bool near_hi = inv_direction[a] < 0;  // the near plane is the box's hi side
            inv[a] = float(inv_direction[a]);           // +-0 directions give +-inf, whose sign is kept
            origin_near[a] = near_hi ? below[a] : above[a];
            origin_far[a] = near_hi ? above[a] : below[a];
            octant |= near_hi ? 1u << a : 0;
        }
    }
};

// Where a node's near and far planes along axis a are, for rays of one octant.
template <int W, unsigned kOctant>
constexpr std::size_t near_offset(int a) {
    return (kOctant >> a & 1 ? offsetof(WideNode<W>, hi) : offsetof(WideNode<W>, lo)) +
           std::size_t(a) * sizeof(float[W]);
}
template <int W, unsigned kOctant>
constexpr std::size_t far_offset(int a) {
    return near_offset<W, (kOctant ^ 7u)>(a);  // the far side is the near one of the opposite octant
}

// What follows computes in lanes, and so is compiled one way per choice of core/wide_lanes.hpp.
inline namespace RTLAB_LANES_NAMESPACE {

// The ray as the node test reads it: each value in all W lanes, made once per query, so
// that a visit takes them as operands instead of spreading them out again. Ahead of the
// origin (kAhead) the slack is folded into the reciprocals: every distance that can decide
// the answer is then >= 0 and within a few float epsilons of its exact value *relatively*,
// so measuring entries with 1/d shrunk by kSlack and exits with 1/d grown by it puts each
// on its safe side (a distance that comes out negative is one whose exact value is
// negative too: rounding keeps signs, so it can only lose to tmin). Otherwise both use
// 1/d, and enter() widens the interval after.
//
// The origin is kept negated: plane + (-o) is plane - o to the bit, and an addition can
// read the plane straight from memory where a subtraction from it needs it loaded first
// (bunny shadow rays, callgrind: 965 -> 958 instructions unblocked, 1,049 -> 1,042 blocked;
// the compiler keeps only some of the six in registers).
template <int W>
struct RayLanes {
    using F = typename FloatLanes<W>::type;
    F minus_origin_near[3], minus_origin_far[3], inv_near[3], inv_far[3];

    RayLanes(const WideRay<W>& r, bool ahead) {
#pragma GCC unroll 3
        for (int a = 0; a < 3; ++a) {
            splat(minus_origin_near[a], -r.origin_near[a]);
            splat(minus_origin_far[a], -r.origin_far[a]);
            splat(inv_near[a], ahead ? r.inv[a] * (1 - WideRay<W>::kSlack) : r.inv[a]);
            splat(inv_far[a], ahead ? r.inv[a] * (1 + WideRay<W>::kSlack) : r.inv[a]);
        }
    }
};

template <int W>
using LaneMask = decltype(typename FloatLanes<W>::type{} < typename FloatLanes<W>::type{});

// Where the ray enters each child's box within [tmin, tmax] (float bounds, already rounded
// outwards, in every lane), lowered to be safe, in t; entered marks the children it enters,
// and the return value has bit c set for child c among them.
template <bool kAhead, unsigned kOctant, int W>
inline unsigned enter(const WideNode<W>& node, const RayLanes<W>& ray, const typename FloatLanes<W>::type& tmin,
                      const typename FloatLanes<W>::type& tmax, typename FloatLanes<W>::type& t, LaneMask<W>& entered) {
    using F = typename FloatLanes<W>::type;
    // A node's planes are whole, aligned vectors (W floats from a 64-byte boundary).
    using Plane [[gnu::may_alias]] = F;
    F near[3], far[3];
    const char* base = reinterpret_cast<const char*>(&node);
    for (int a = 0; a < 3; ++a) {
        near[a] = (ray.minus_origin_near[a] + *reinterpret_cast<const Plane*>(base + near_offset<W, kOctant>(a))) *
                  ray.inv_near[a];
        far[a] = (ray.minus_origin_far[a] + *reinterpret_cast<const Plane*>(base + far_offset<W, kOctant>(a))) *
                 ray.inv_far[a];
    }
    // The largest entry and smallest exit, as a tree (shorter than a chain). A NaN (0 * inf:
    // the ray lies in a slab's plane) makes `x > y ? x : y` give y: in the inner pair, at
    // worst the other distance is dropped (the interval only grows); the outer pair has the
    // bound that is never NaN second, so the NaN goes no further.
    const F lo_x = near[0] > tmin ? near[0] : tmin, lo_yz = near[1] > near[2] ? near[1] : near[2];
    const F hi_x = far[0] < tmax ? far[0] : tmax, hi_yz = far[1] < far[2] ? far[1] : far[2];
    F lo = lo_yz > lo_x ? lo_yz : lo_x;
    F hi = hi_yz < hi_x ? hi_yz : hi_x;
    // The tiny absolute term covers products that underflowed to denormals.
    constexpr float tiny = std::numeric_limits<float>::min();
    if constexpr (kAhead) {
        entered = lo <= hi + tiny;
        t = lo;
    } else {
        const F abs_lo = lo < 0 ? -lo : lo, abs_hi = hi < 0 ? -hi : hi;
        lo -= abs_lo * WideRay<W>::kSlack;
        hi += abs_hi * WideRay<W>::kSlack + tiny;
        entered = lo <= hi;
        t = lo;
    }
    return lane_mask(F(entered));
}

// For each mask of eight lanes, the lanes that are set, highest first (the rest 0): the
// shuffle that packs the children a ray enters together, farthest on the bottom.
struct PackTable {
    alignas(32) std::uint32_t lanes[256][8];
};
constexpr PackTable make_pack_table() {
    PackTable table{};
    for (unsigned m = 0; m < 256; ++m) {
        int n = 0;
        for (int lane = 7; lane >= 0; --lane)
            if (m >> lane & 1) table.lanes[m][n++] = std::uint32_t(lane);
    }
    return table;
}
inline constexpr PackTable kPackTable = make_pack_table();

// Writes the children that `entered` marks to the stack (refs, ts) in the octant's order,
// the nearest last, and returns how many; `nearest` is that last one, which the caller
// follows at once (so it is not read back from the stack: that would wait for the store).
// Eight at a time with AVX2: one shuffle puts the slots in order and packs the entered ones
// together, and one store each writes them (the stack has room for W beyond its top).
// Elsewhere, the same order one slot at a time. A packet's search (core/wide_packet.hpp)
// also moves a word per child along with them, `payload`, slot by slot, into `payloads`,
// the nearest's into `nearest_payload`.
template <unsigned kOctant, int W>
inline int push_children(const WideNode<W>& node, unsigned mask, const typename FloatLanes<W>::type& t,
                         const LaneMask<W>& entered, std::uint32_t* refs, float* ts, std::uint32_t& nearest,
                         const std::uint32_t* payload = nullptr, std::uint32_t* payloads = nullptr,
                         std::uint32_t* nearest_payload = nullptr) {
    constexpr int octant_shift = 3 * int(kOctant);
#ifdef RTLAB_LANES_AVX2
    if constexpr (W == 8) {
        const __m256i order =
            _mm256_srli_epi32(_mm256_load_si256(reinterpret_cast<const __m256i*>(node.order)), octant_shift);
        const unsigned ordered = unsigned(_mm256_movemask_ps(_mm256_permutevar8x32_ps(__m256(entered), order)));
        const unsigned first = node.order[std::countr_zero(ordered)] >> octant_shift & 7;
        nearest = node.child[first];
        const __m256i pick = _mm256_permutevar8x32_epi32(
            order, _mm256_load_si256(reinterpret_cast<const __m256i*>(kPackTable.lanes[ordered])));
        _mm256_storeu_si256(
            reinterpret_cast<__m256i*>(refs),
            _mm256_permutevar8x32_epi32(_mm256_load_si256(reinterpret_cast<const __m256i*>(node.child)), pick));
        _mm256_storeu_ps(ts, _mm256_permutevar8x32_ps(__m256(t), pick));
        if (payload) {
            _mm256_storeu_si256(
                reinterpret_cast<__m256i*>(payloads),
                _mm256_permutevar8x32_epi32(_mm256_load_si256(reinterpret_cast<const __m256i*>(payload)), pick));
            *nearest_payload = payload[first];
        }
        return std::popcount(ordered);
    }
#endif
    (void)entered;
    int slots[W], n = 0;
    for (int p = 0; p < W; ++p) {
        const int slot = int(node.order[p] >> octant_shift & 7);
        if (mask >> slot & 1) slots[n++] = slot;
    }
    for (int i = 0; i < n; ++i) {
        refs[i] = node.child[slots[n - 1 - i]];
        ts[i] = t[slots[n - 1 - i]];
        if (payload) payloads[i] = payload[slots[n - 1 - i]];
    }
    nearest = node.child[slots[0]];
    if (payload) *nearest_payload = payload[slots[0]];
    return n;
}

// The `count` children just postponed (refs[0] on), asked for whole from memory now: on a
// big mesh each is a likely trip to memory, and it is then on its way while the search works
// elsewhere (book §C.2 records what asking for only the next two cost). A node's lines are
// prefetched here, a leaf's items by the caller's fetch(first). The child followed at once is
// read at once anyway.
template <int W, class Fetch>
inline void ask_for_postponed(const WideBvh<W>& bvh, const std::uint32_t* refs, int count, Fetch& fetch) {
    for (int i = 0; i < count; ++i) {
        const std::uint32_t child = refs[i];
        if (is_leaf(child)) {
            fetch(leaf_first(child));
        } else {
            const char* p = reinterpret_cast<const char*>(&bvh.nodes[child]);
            for (int line = 0; line < int(sizeof(WideNode<W>)); line += 64) __builtin_prefetch(p + line);
        }
    }
}

// Both queries walk the tree the same way: the children a ray enters go on a stack with
// their entry distances, in the order its direction's octant gives (WideNode::order), and the
// top one is taken next. A leaf is tested whole, leaf(first, count, interval): the caller
// keeps its items together (geometry/triangle_block.hpp). As soon as a child is postponed its
// memory is asked for: a node here, a leaf through fetch(first), so that on a big mesh, where
// each visit can be a trip to memory, it is on its way when its turn comes. A node with one
// child entered pushes nothing: the search goes straight on (about half the visits of a
// primary ray on the bunny).
// - The closest hit (kAny false): leaf narrows interval.max and returns true when it finds a
//   closer hit, and a child whose entry lies beyond the best hit found since it was pushed is
//   skipped.
// - Any hit (kAny true): the first leaf that returns true ends the search.
// kAhead: interval.min >= 0, which lets enter() take its cheaper form.
template <bool kAny, bool kAhead, unsigned kOctant, int W, class Leaf, class Fetch>
bool traverse_from(const WideBvh<W>& bvh, const WideRay<W>& r, Interval interval, Leaf&& leaf, Fetch&& fetch) {
    if (bvh.nodes.empty() && !bvh.root_is_leaf) return false;
    TallyScope tally;
    TraversalCount& count = tally.count;
    if (bvh.root_is_leaf) {
        count.items += bvh.root_count;
        return leaf(0, bvh.root_count, interval);
    }
    using F = typename FloatLanes<W>::type;
    const float tmin = float_below(interval.min);  // >= 0 when interval.min is
    float tmax = float_above(widen_far(interval.max));
    const RayLanes<W> lanes(r, kAhead);
    F tmin_v, tmax_v;
    splat(tmin_v, tmin);
    splat(tmax_v, tmax);
    // Each visit follows one child and postpones at most W - 1, and the store writes W slots.
    constexpr int kStack = (W - 1) * kMaxBvhDepth + W + 1;
    alignas(32) std::uint32_t refs[kStack];
    alignas(32) float ts[kStack];
    int top = 0;
    std::uint32_t ref = 0;  // the root
    bool found = false;
    for (;;) {
        if (is_leaf(ref)) {
            count.items += leaf_count(ref);
            if (leaf(leaf_first(ref), leaf_count(ref), interval)) {
                if (kAny) return true;
                found = true;
                tmax = float_above(widen_far(interval.max));
                splat(tmax_v, tmax);
            }
        } else {
            const WideNode<W>& node = bvh.nodes[ref];
            // The line after the planes (which children, in what order) is read only once the
            // test is done: asked for now, a trip to memory overlaps the planes' own.
            __builtin_prefetch(node.child);
            F t;
            LaneMask<W> entered;
            const unsigned mask = enter<kAhead, kOctant>(node, lanes, tmin_v, tmax_v, t, entered);
            count.nodes += W;
            if (std::has_single_bit(mask)) {  // one child: follow it, nothing to push
                ref = node.child[std::countr_zero(mask)];
                continue;
            }
            if (mask != 0) {
                const int n = push_children<kOctant>(node, mask, t, entered, refs + top, ts + top, ref);
                ask_for_postponed(bvh, refs + top, n - 1, fetch);
                top += n - 1;
                continue;
            }
        }
        // Next: the nearest postponed child still in front of the best hit.
        for (;;) {
            if (top == 0) return found;
            --top;
            if (kAny || ts[top] <= tmax) break;
        }
        ref = refs[top];
    }
}

// The search compiled for each octant (the planes' places in a node become constants, which
// the loop would otherwise keep in registers it has too few of) and each kind of interval.
template <bool kAny, int W, class Leaf, class Fetch, unsigned... kOctants>
bool traverse_octant(const WideBvh<W>& bvh, const WideRay<W>& ray, Interval interval, Leaf&& leaf, Fetch&& fetch,
                     std::integer_sequence<unsigned, kOctants...>) {
    bool found = false;
    const bool ahead = interval.min >= 0;
    (void)((ray.octant == kOctants &&
            (found = ahead ? traverse_from<kAny, true, kOctants>(bvh, ray, interval, leaf, fetch)
                           : traverse_from<kAny, false, kOctants>(bvh, ray, interval, leaf, fetch),
             true)) ||
           ...);
    return found;
}

template <bool kAny, int W, class Leaf, class Fetch>
bool traverse(const WideBvh<W>& bvh, const WideRay<W>& ray, Interval interval, Leaf&& leaf, Fetch&& fetch) {
    return traverse_octant<kAny>(bvh, ray, interval, leaf, fetch, std::make_integer_sequence<unsigned, 8>{});
}

template <int W, class Leaf, class Fetch>
bool closest_hit(const WideBvh<W>& bvh, const WideRay<W>& ray, Interval interval, Leaf&& leaf, Fetch&& fetch) {
    return traverse<false>(bvh, ray, interval, leaf, fetch);
}

template <int W, class Leaf, class Fetch>
bool any_hit(const WideBvh<W>& bvh, const WideRay<W>& ray, Interval interval, Leaf&& leaf, Fetch&& fetch) {
    return traverse<true>(bvh, ray, interval, leaf, fetch);
}

// Every leaf whose box the ray enters within `interval`, each once, in no order to rely on:
// leaf(first, count, interval) is shown them all (CSG collects every crossing of a mesh).
// It is the any-hit search with a leaf that never reports a hit, so nothing ends it early.
template <int W, class Leaf, class Fetch>
void for_each_leaf_entered(const WideBvh<W>& bvh, const WideRay<W>& ray, Interval interval, Leaf&& leaf,
                           Fetch&& fetch) {
    traverse<true>(
        bvh, ray, interval,
        [&](std::uint32_t first, std::uint32_t count, Interval& iv) {
            leaf(first, count, iv);
            return false;
        },
        fetch);
}

}  // namespace RTLAB_LANES_NAMESPACE

}  // namespace rt
