#pragma once
// Four triangles side by side, so that a BVH leaf is tested in one pass of four-lane vector
// instructions instead of four calls (book §10.5). The pass is a filter in float: it runs
// the watertight test's arithmetic (exercise 3.2) on all four lanes and keeps every
// triangle that the exact test might accept, with margins that bound float's rounding.
// The triangles it keeps are then decided by ray_triangle_watertight itself, in Real, so
// the hits are exactly brute force's; only an occlusion query, which needs no t, takes a
// hit the float pass proves certain without the exact test (blocks_ray).
#include "core/ray.hpp"
#include "core/wide_bvh.hpp"
#include "geometry/triangle.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>

namespace rt {

// Four triangles side by side, in float: a block is three cache lines, the size Embree's
// leaves have. The exact test needs the corners in Real. Where float holds them exactly
// (a mesh read from a file: OBJ coordinates are read as floats) the block's own are
// they, already in cache; otherwise they are read from a second array in the same order
// (MeshAccel::corners), a trip to memory on a big mesh.
struct alignas(64) TriangleBlock {
    float p[3][3][4];         // p[corner][axis][lane]
    float size[4];            // the largest |coordinate| of the lane's corners, rounded up
    std::uint32_t index[4];   // each lane's triangle number
    std::uint32_t count = 0;  // lanes in use, from 0
    bool exact = false;       // p holds every corner exactly
};

// A lane's corners in Real, from the block's floats (exact: see TriangleBlock::exact).
inline std::array<Vec3, 3> lane_corners(const TriangleBlock& block, int lane) {
    std::array<Vec3, 3> c;
    for (int v = 0; v < 3; ++v) c[std::size_t(v)] = Vec3(block.p[v][0][lane], block.p[v][1][lane], block.p[v][2][lane]);
    return c;
}

// The watertight test's view of a ray, in float, once per ray instead of once per triangle:
// the axis where the direction is largest becomes z, and the shear that makes the ray point
// along +z (course §9.3.2; book §3.4), chosen as exercise 3.2 chooses them.
struct RayShear {
    // In the order kx, ky, kz: the origin's coordinates, and the byte offset of axis k's
    // lanes in a block's corner (of p[v][k] from p[v]), so that a leaf reads them as they are.
    float origin[3];
    std::size_t offset[3];
    float origin_size;  // the largest |coordinate| of the origin, rounded up
    float sx, sy, sz;

    RayShear() = default;  // to be assigned one of the others (a packet's rays make theirs when needed)
    explicit RayShear(const Ray& ray) : RayShear(ray, Real(1) / ray.direction) {}
    // inv_direction: 1 / ray.direction, when the caller has it already.
    RayShear(const Ray& ray, const Vec3& inv_direction);
};

namespace block_detail {

using Lanes = FloatLanes<4>::type;
using Mask = decltype(Lanes{} < Lanes{});

inline unsigned bits(Mask m) {
    return lane_mask(Lanes(m));
}

// |v|: the sign bit cleared (one instruction; `v < 0 ? -v : v` is three).
inline Lanes magnitude(Lanes v) {
    using Bits = decltype(v < v);
    return Lanes(Bits(v) & 0x7fffffff);
}

inline Lanes load(const float (&lanes)[4]) {
    Lanes v;
    std::memcpy(&v, lanes, sizeof v);
    return v;
}

// The lanes of corner p[v] along the axis at byte `offset` (RayShear::offset).
inline Lanes load(const float (&corner)[3][4], std::size_t offset) {
    Lanes v;
    std::memcpy(&v, reinterpret_cast<const char*>(corner) + offset, sizeof v);
    return v;
}

inline Lanes larger(Lanes a, Lanes b) {
    return a > b ? a : b;
}
inline Lanes smaller(Lanes a, Lanes b) {
    return a < b ? a : b;
}

inline constexpr float u = 0x1p-24f;  // float's unit roundoff

}  // namespace block_detail

// What the float pass says about each lane of a block: bit i of `maybe` for each lane
// whose triangle the ray might hit for t in the interval (every one exercise 3.2's exact
// test could accept, and a few more), and of `surely` for each whose hit is certain
// beyond rounding (a subset of `maybe`).
struct BlockLanes {
    unsigned maybe = 0, surely = 0;
};

// The float pass over a block.
//
// It is the exercise's arithmetic in float, with a bound on how far each result can be from
// the exact one (the usual forward error analysis, rounded up generously):
// - a sheared corner coordinate (x, y) is within E = 16 u (corner size + origin size): the
//   corner and the origin each rounded to float, their difference, the shear's product and
//   difference each rounded once;
// - an edge function, two products of such coordinates (each at most R + E) less each other,
//   is within m = 4 (R + E) E + 4 u (R + E)^2;
// - det = U + V + W and T = U za + V zb + W zc likewise, within err_det and err_T.
// A lane is dropped only when its edge functions disagree in sign by more than m, or when its
// t is surely outside the interval: behind the origin beyond doubt, or, where det and T are
// over 1024 times their error (so t is good to 2^-9), more than 2^-8 of t outside.
//
// kDistances false stops after the edge functions: `maybe` then keeps every lane whose
// triangle the ray's line might cross, whatever its t, and `surely` is empty. That is what
// the closest-hit search asks (candidates): on the bunny the t tests cost ~160 instructions
// per hit ray and saved almost no exact tests, which check t themselves.
template <bool kDistances = true>
[[gnu::always_inline]] inline BlockLanes classify(const TriangleBlock& block, const RayShear& r, Interval interval) {
    using namespace block_detail;
    Lanes x[3], y[3], z[3];  // corner v sheared: x[v], y[v]; z[v] along the ray's main axis
    for (int v = 0; v < 3; ++v) {
        const Lanes a = load(block.p[v], r.offset[0]) - r.origin[0];
        const Lanes b = load(block.p[v], r.offset[1]) - r.origin[1];
        z[v] = load(block.p[v], r.offset[2]) - r.origin[2];
        x[v] = a - r.sx * z[v];
        y[v] = b - r.sy * z[v];
    }
    const Lanes R = larger(larger(larger(magnitude(x[0]), magnitude(y[0])), larger(magnitude(x[1]), magnitude(y[1]))),
                           larger(magnitude(x[2]), magnitude(y[2])));
    const Lanes E = (load(block.size) + r.origin_size) * (16 * u) + 0x1p-100f;
    const Lanes RE = R + E, RE2 = RE * RE;
    const Lanes m = RE * (4 * E + (4 * u) * RE) + 0x1p-100f;

    const Lanes U = x[2] * y[1] - y[2] * x[1];
    const Lanes V = x[0] * y[2] - y[0] * x[2];
    const Lanes W = x[1] * y[0] - y[1] * x[0];
    // All three >= -m or all three <= m, through the least and the greatest. A lane with a
    // NaN (an overflow) is dropped, as the comparisons one by one drop it, or kept for the
    // exact test to decide: never a lane they keep dropped.
    const Mask inside = (smaller(smaller(U, V), W) >= -m) | (larger(larger(U, V), W) <= m);
    const unsigned used = (1u << block.count) - 1;
    const unsigned keep = bits(inside) & used;
    if (!kDistances || keep == 0) return {keep, 0};

    const Lanes za = r.sz * z[0], zb = r.sz * z[1], zc = r.sz * z[2];
    const Lanes det = U + V + W, T = U * za + V * zb + W * zc;
    const Lanes Z = larger(larger(magnitude(za), magnitude(zb)), magnitude(zc));
    const Lanes Ez = E * std::abs(r.sz);
    const Lanes err_det = 3 * m + (8 * u) * RE2;
    const Lanes err_T = 3 * (m * (Z + Ez) + 2 * RE2 * Ez + (4 * u) * RE2 * Z);
    // With det made positive, T's sign is t's.
    const Lanes det_p = magnitude(det), T_p = det < 0 ? -T : T;
    Mask out = Mask{};
    if (interval.min >= 0) out = (det_p > err_det) & (T_p + err_T < 0);
    const Mask sure = (det_p > 1024 * err_det) & (T_p > 1024 * err_T);
    // t = T / det compared without dividing: det_p > 0 wherever `sure` holds.
    out |= sure &
           ((T_p * (1 - 0x1p-8f) > det_p * float(interval.max)) | (T_p * (1 + 0x1p-8f) < det_p * float(interval.min)));
    // Most blocks a shadow ray reaches end here: the t tests drop the lanes the edge
    // functions kept (the triangle the ray leaves lies behind its origin).
    const unsigned left = keep & ~bits(out);
    if (left == 0) return {0, 0};

    // A certain hit: every edge function beyond twice its error bound with one sign (the
    // exact test, whose own error is at most the bound, sees that sign too), and t inside
    // the interval for every T and det within twice their bounds; 2^-20 covers the rounding
    // of the comparison's own products.
    const Lanes m2 = 2 * m;
    const Mask signs = ((U > m2) & (V > m2) & (W > m2)) | ((U < -m2) & (V < -m2) & (W < -m2));
    const Lanes det_lo = det_p - 2 * err_det, T_lo = T_p - 2 * err_T, T_hi = T_p + 2 * err_T;
    Mask within = (det_lo > 0) & (T_lo > 0) & (T_hi * (1 + 0x1p-20f) < det_lo * float(interval.max));
    if (interval.min > 0) within &= T_lo > (det_p + 2 * err_det) * float(interval.min) * (1 + 0x1p-20f);
    return {left, bits(signs & within) & used};
}

// The lanes whose triangle the ray's line might cross (classify's `maybe` without the t
// tests); the exact test then decides each, t included.
[[gnu::always_inline]] inline unsigned candidates(const TriangleBlock& block, const RayShear& r, Interval interval) {
    return classify<false>(block, r, interval).maybe;
}

// Asks the memory system for a block that a search is about to test.
inline void prefetch(const TriangleBlock& block) {
    const char* p = reinterpret_cast<const char*>(&block);
    for (std::size_t line = 0; line < sizeof block; line += 64) __builtin_prefetch(p + line);
}

// for_each_hit calls f(triangle, hit, its corners) for each triangle of the block that
// exercise 3.2's exact test finds in the interval, lane by lane, until f returns true, and
// returns whether it did; exact_hits does the same for the lanes given (bit i for lane i).
// corners[lane] holds the lane's corners in Real; it is read only for a block that is not
// exact, and may be null for one that is.
template <class F>
bool exact_hits(unsigned lanes, const TriangleBlock& block, const std::array<Vec3, 3>* corners, const Ray& ray,
                Interval interval, F&& f) {
    for (; lanes != 0; lanes &= lanes - 1) {
        const int lane = std::countr_zero(lanes);
        const std::array<Vec3, 3> c = block.exact ? lane_corners(block, lane) : corners[lane];
        TriangleHit h;
        if (ray_triangle_watertight(ray, c[0], c[1], c[2], interval, h) && f(block.index[lane], h, c)) return true;
    }
    return false;
}
template <class F>
bool for_each_hit(const TriangleBlock& block, const std::array<Vec3, 3>* corners, const RayShear& shear, const Ray& ray,
                  Interval interval, F&& f) {
    return exact_hits(candidates(block, shear, interval), block, corners, ray, interval, f);
}

// Does any triangle of the block meet the ray in the interval? A hit the float pass finds
// certain needs no exact test (an occlusion query asks for no t and no triangle); the others
// the filter keeps go to exercise 3.2's test.
//
// The filter is inline in the search, the exact test out of line: it is rare (one block in
// a thousand on the bunny's unblocked shadow rays), and a call costs the search more than the
// filter itself: every vector register is the caller's to save, and the search keeps the
// ray's lanes in ten (book §C.2).
bool blocks_ray_exactly(unsigned lanes, const TriangleBlock& block, const std::array<Vec3, 3>* corners, const Ray& ray,
                        Interval interval);

// corners() gives the block's corners in Real (as for exact_hits), asked only when the exact
// test runs: worked out in every leaf, it cost about ten instructions a leaf.
template <class Corners>
[[gnu::always_inline]] inline bool blocks_ray(const TriangleBlock& block, Corners&& corners, const RayShear& shear,
                                              const Ray& ray, Interval interval) {
    const BlockLanes lanes = classify(block, shear, interval);
    return lanes.surely != 0 || (lanes.maybe != 0 && blocks_ray_exactly(lanes.maybe, block, corners(), ray, interval));
}

// Triangles packed four to a block in the order given.
TriangleBlock pack(std::span<const std::uint32_t> triangles, const Vec3* positions,
                   const std::array<std::uint32_t, 3>* corners);

}  // namespace rt
