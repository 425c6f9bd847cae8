#pragma once
// Rays that leave one point, searched together (book §10.5). A pinhole camera's rays all
// start at the eye, and the rays of neighbouring pixels go almost the same way, so they
// enter almost the same boxes: searched one at a time, each ray repeats its neighbours' box
// tests. A packet of up to eight such rays walks the wide BVH of core/wide_bvh.hpp once:
// - an inner node's eight boxes are tested against the whole packet at once, by interval
//   arithmetic over the rays' reciprocal directions (a frustum test): a box is entered when
//   any ray of the packet might enter it (Wald et al. 2001's packets, Reshetov et al. 2005's
//   frusta, Overbeck et al. 2008's ranged traversal);
// - a leaf's box is then tested against each ray alone, with that ray's own far end, by the
//   single ray's test (its 1/d rounded once more, well within the slack); only the rays that
//   enter it test its items.
// Both tests are conservative, as core/wide_bvh.hpp's is (the interval's bounds are taken
// over the same rounded numbers, and rounding keeps their order), so every leaf a ray's own
// search would test, this search tests for it: the hits are the same, bit for bit, whatever
// the order (geometry/hit_record.hpp, closer). What changes is the work: on a bunny framed
// by a 1024 x 1024 camera, a packet of 2 x 4 pixels visits about 3 nodes where its eight
// rays one at a time visit about 18 (book §10.7 measures it).
#include "core/wide_bvh.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>

namespace rt {

inline constexpr int kPacketRays = 8;  // one AVX register of floats, a lane per ray

// A packet's answer when its rays are searched one by one (a structure without a packet
// search, or rays that cannot be a packet): bit k set where hit(k) found ray k's hit.
template <class Hit>
unsigned one_by_one(std::size_t count, Hit&& hit) {
    unsigned found = 0;
    for (std::size_t k = 0; k < count; ++k) found |= unsigned(hit(k)) << k;
    return found;
}

inline namespace RTLAB_LANES_NAMESPACE {

// A packet made ready for the search: what WideRay is for one ray, lane k for ray k.
struct WidePacket {
    using F = FloatLanes<kPacketRays>::type;
    int count = 0;        // rays, 1 to 8
    unsigned octant = 0;  // their directions' common octant (WideRay::octant)
    float tmin = 0;       // their common start, rounded down (>= 0)
    // The common origin rounded each way (WideRay's origin_near and origin_far).
    float origin_near[3], origin_far[3];
    // 1/d of each ray, shrunk and grown by WideRay::kSlack (lanes past `count` repeat ray 0),
    // and the range of each over the rays: what the frustum test multiplies by.
    F inv_near[3], inv_far[3];
    float inv_near_lo[3], inv_near_hi[3], inv_far_lo[3], inv_far_hi[3];
    F tmax;  // each ray's far end, rounded up and widened (widen_far); -inf past `count`

    unsigned all() const { return (1u << count) - 1; }
    // Ray k's search found a hit at t: its far end comes in to it.
    void narrow(int k, Real t) { tmax[k] = float_above(widen_far(t)); }
};

namespace packet_detail {

// The least and the greatest of the lanes, in three halvings: each lane against the one
// half, then a quarter, then an eighth of the way round.
inline float least(WidePacket::F v) {
    WidePacket::F w = __builtin_shufflevector(v, v, 4, 5, 6, 7, 0, 1, 2, 3);
    v = v < w ? v : w;
    w = __builtin_shufflevector(v, v, 2, 3, 0, 1, 6, 7, 4, 5);
    v = v < w ? v : w;
    w = __builtin_shufflevector(v, v, 1, 0, 3, 2, 5, 4, 7, 6);
    v = v < w ? v : w;
    return v[0];
}
inline float greatest(WidePacket::F v) {
    return -least(-v);
}

}  // namespace packet_detail

// Makes `p` the packet of `rays` (1 to 8 of them) searched over `interval`, or returns false
// when they cannot go together, and each must be searched alone: origins that differ, an
// interval that starts behind the origin, directions in different octants, or a direction
// component under float's smallest normal number (1/d would be infinite, or lose its
// precision) or not finite.
inline bool make_packet(std::span<const Ray> rays, Interval interval, WidePacket& p) {
    using F = WidePacket::F;
    const int n = int(rays.size());
    if (n < 1 || n > kPacketRays || !(interval.min >= 0)) return false;
    const Ray& first = rays[0];
    for (int k = 1; k < n; ++k)
        if (!(rays[std::size_t(k)].origin == first.origin)) return false;
    F d[3];
    for (int k = 0; k < kPacketRays; ++k)
        for (int a = 0; a < 3; ++a) d[a][k] = float(rays[std::size_t(k < n ? k : 0)].direction[a]);
    unsigned octant = 0;
    for (int a = 0; a < 3; ++a) {
        using Bits = decltype(d[a] < d[a]);
        const F size = F(Bits(d[a]) & 0x7fffffff);
        // Every component finite and of normal size (NaN fails too), and all of one sign.
        if (lane_mask(F((size >= std::numeric_limits<float>::min()) & (size <= std::numeric_limits<float>::max()))) !=
            0xffu)
            return false;
        const unsigned negative = lane_mask(d[a]);
        if (negative != 0 && negative != 0xffu) return false;
        octant |= negative != 0 ? 1u << a : 0;
    }
    p.count = n;
    p.octant = octant;
    p.tmin = float_below(interval.min);
    float below[3], above[3];
    float_bounds(first.origin, below, above);
    F one;
    splat(one, 1.0f);
    for (int a = 0; a < 3; ++a) {
        const bool near_hi = octant >> a & 1;  // the near plane is the box's hi side
        p.origin_near[a] = near_hi ? below[a] : above[a];
        p.origin_far[a] = near_hi ? above[a] : below[a];
        // float(d) and the division round twice where WideRay rounds once: well inside the
        // slack's 16 float epsilons. Lanes past n repeat ray 0, so the ranges are the rays'.
        const F inv = one / d[a];
        const F inv_near = inv * (1 - WideRay<kPacketRays>::kSlack), inv_far = inv * (1 + WideRay<kPacketRays>::kSlack);
        p.inv_near[a] = inv_near;
        p.inv_far[a] = inv_far;
        p.inv_near_lo[a] = packet_detail::least(inv_near);
        p.inv_near_hi[a] = packet_detail::greatest(inv_near);
        p.inv_far_lo[a] = packet_detail::least(inv_far);
        p.inv_far_hi[a] = packet_detail::greatest(inv_far);
    }
    const float far = float_above(widen_far(interval.max));
    for (int k = 0; k < kPacketRays; ++k) p.tmax[k] = k < n ? far : -std::numeric_limits<float>::infinity();
    return true;
}

// The closest hit of every ray of the packet: the search of core/wide_bvh.hpp's closest_hit,
// each node's boxes tested once for all its rays. leaf(first, count, rays) tests the items of
// a leaf for the rays that enter its box (bit k for ray k), each ray over its own interval,
// and calls p.narrow(k, t) for each ray that found a closer hit, returning whether any did.
// A child is skipped when the packet enters it beyond the farthest of the rays' far ends.
template <unsigned kOctant, class Leaf, class Fetch>
void closest_hits_from(const WideBvh<kPacketRays>& bvh, WidePacket& p, Leaf&& leaf, Fetch&& fetch) {
    constexpr int W = kPacketRays;
    using F = WidePacket::F;
    if (bvh.nodes.empty() && !bvh.root_is_leaf) return;
    TallyScope tally;
    TraversalCount& count = tally.count;
    const unsigned all = p.all();
    if (bvh.root_is_leaf) {
        count.items += std::uint64_t(bvh.root_count) * std::uint64_t(p.count);
        leaf(0, bvh.root_count, all);
        return;
    }
    F tmin_v, tmax_v;
    splat(tmin_v, p.tmin);
    float tmax = packet_detail::greatest(p.tmax);
    splat(tmax_v, tmax);
    F origin_near[3], origin_far[3], near_lo[3], near_hi[3], far_lo[3], far_hi[3];
    for (int a = 0; a < 3; ++a) {
        splat(origin_near[a], p.origin_near[a]);
        splat(origin_far[a], p.origin_far[a]);
        splat(near_lo[a], p.inv_near_lo[a]);
        splat(near_hi[a], p.inv_near_hi[a]);
        splat(far_lo[a], p.inv_far_lo[a]);
        splat(far_hi[a], p.inv_far_hi[a]);
    }
    constexpr float tiny = std::numeric_limits<float>::min();  // as in enter()
    constexpr int kStack = (W - 1) * kMaxBvhDepth + W + 1;
    alignas(32) std::uint32_t refs[kStack];
    alignas(32) float ts[kStack];
    alignas(32) std::uint32_t masks[kStack];  // which rays each postponed child is for
    int top = 0;
    std::uint32_t ref = 0, rays = all;  // the root, for every ray
    for (;;) {
        if (is_leaf(ref)) {
            count.items += std::uint64_t(leaf_count(ref)) * std::uint64_t(std::popcount(rays));
            if (leaf(leaf_first(ref), leaf_count(ref), rays)) {
                tmax = packet_detail::greatest(p.tmax);
                splat(tmax_v, tmax);
            }
        } else {
            const WideNode<W>& node = bvh.nodes[ref];
            __builtin_prefetch(node.child);
            using Plane [[gnu::may_alias]] = F;
            const char* base = reinterpret_cast<const char*>(&node);
            // Each plane's distance, its lowest (entries) or highest (exits) over the rays:
            // the product is linear in 1/d, so one of the range's two ends gives it.
            F near[3], far[3];
            for (int a = 0; a < 3; ++a) {
                const F dn = *reinterpret_cast<const Plane*>(base + near_offset<W, kOctant>(a)) - origin_near[a];
                const F x = dn * near_lo[a], y = dn * near_hi[a];
                near[a] = x < y ? x : y;
                const F df = *reinterpret_cast<const Plane*>(base + far_offset<W, kOctant>(a)) - origin_far[a];
                const F u = df * far_lo[a], v = df * far_hi[a];
                far[a] = u > v ? u : v;
            }
            const F lo_x = near[0] > tmin_v ? near[0] : tmin_v, lo_yz = near[1] > near[2] ? near[1] : near[2];
            const F hi_x = far[0] < tmax_v ? far[0] : tmax_v, hi_yz = far[1] < far[2] ? far[1] : far[2];
            const F lo = lo_yz > lo_x ? lo_yz : lo_x;
            const F hi = hi_yz < hi_x ? hi_yz : hi_x;
            unsigned mask = lane_mask(F(lo <= hi + tiny));
            count.nodes += W;
            // The leaves among the children entered, each tested against each ray with the
            // single ray's own arithmetic (enter()'s, with that ray's far end): a ray tests
            // the items of a leaf only if its own search would have.
            alignas(32) std::uint32_t child_rays[W];
            for (int c = 0; c < W; ++c) child_rays[c] = rays;
            F refs_as_floats;  // a leaf's reference has the top bit set (kLeafRef): a float's sign
            std::memcpy(&refs_as_floats, node.child, sizeof refs_as_floats);
            for (unsigned leaves = mask & lane_mask(refs_as_floats); leaves != 0; leaves &= leaves - 1) {
                const int c = std::countr_zero(leaves);
                F entry = tmin_v, exit = p.tmax;
                for (int a = 0; a < 3; ++a) {
                    const float* near_plane = (kOctant >> a & 1) ? node.hi[a] : node.lo[a];
                    const float* far_plane = (kOctant >> a & 1) ? node.lo[a] : node.hi[a];
                    F dn, df;
                    splat(dn, near_plane[c] - p.origin_near[a]);
                    splat(df, far_plane[c] - p.origin_far[a]);
                    const F x = dn * p.inv_near[a], y = df * p.inv_far[a];
                    entry = x > entry ? x : entry;
                    exit = y < exit ? y : exit;
                }
                count.nodes += std::uint64_t(std::popcount(rays));
                child_rays[c] = lane_mask(F(entry <= exit + tiny)) & rays;
                if (child_rays[c] == 0) mask &= ~(1u << c);
            }
            if (std::has_single_bit(mask)) {
                const int c = std::countr_zero(mask);
                ref = node.child[c];
                rays = child_rays[c];
                continue;
            }
            if (mask != 0) {
                using Bits = LaneMask<W>;
                Bits lanes_entered;
                for (int c = 0; c < W; ++c) lanes_entered[c] = mask >> c & 1 ? -1 : 0;
                const int n = push_children<kOctant>(node, mask, lo, lanes_entered, refs + top, ts + top, ref,
                                                     child_rays, masks + top, &rays);
                ask_for_postponed(bvh, refs + top, n - 1, fetch);
                top += n - 1;
                continue;
            }
        }
        for (;;) {
            if (top == 0) return;
            --top;
            if (ts[top] <= tmax) break;
        }
        ref = refs[top];
        rays = masks[top];
    }
}

template <class Leaf, class Fetch>
void closest_hits(const WideBvh<kPacketRays>& bvh, WidePacket& p, Leaf&& leaf, Fetch&& fetch) {
    const auto search_in_octant = [&]<unsigned... kOctants>(std::integer_sequence<unsigned, kOctants...>) {
        (void)((p.octant == kOctants && (closest_hits_from<kOctants>(bvh, p, leaf, fetch), true)) || ...);
    };
    search_in_octant(std::make_integer_sequence<unsigned, 8>{});
}

}  // namespace RTLAB_LANES_NAMESPACE

}  // namespace rt
