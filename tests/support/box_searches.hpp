#pragma once
// The wide BVH's searches over boxes alone (core/wide_bvh.hpp, core/wide_packet.hpp): each
// must meet the nearest box brute force finds for each ray. Included by a file that
// compiles the x86 lanes (test_core.cpp) and by one that compiles the portable lanes
// (test_portable_lanes.cpp): hence the unnamed namespace, a copy for each.
#include "core/wide_packet.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

namespace rt::test {
namespace {

// Uniform numbers in [lo, hi) from a seeded generator, the same on every machine.
struct Uniform {
    std::mt19937 rng;
    explicit Uniform(unsigned seed) : rng(seed) {}
    double operator()(double lo, double hi) { return lo + (hi - lo) * std::ldexp(double(rng()), -32); }
};

// 600 boxes of sizes 0.02 to 0.8 scattered through [0, 10]^3.
inline std::vector<Box> scattered_boxes(Uniform& uniform) {
    std::vector<Box> boxes(600);
    for (Box& b : boxes) {
        const Vec3 c(uniform(0, 10), uniform(0, 10), uniform(0, 10));
        const Vec3 h(uniform(0.01, 0.4), uniform(0.01, 0.4), uniform(0.01, 0.4));
        b.min = c - h;
        b.max = c + h;
    }
    return boxes;
}

// The entry distance of the nearest box the ray meets within the interval, by testing each.
inline Real nearest_box_entry(const std::vector<Box>& boxes, const Ray& ray, Interval interval) {
    Real best = kInfinity;
    for (const Box& box : boxes) {
        Interval iv = interval;
        if (clip_to_box(box, ray, iv) && iv.min < best) best = iv.min;
    }
    return best;
}

// One ray at a time: the closest and the any-hit search, rays in slabs' planes included.
template <int W>
void check_searches() {
    Uniform uniform(29);
    const std::vector<Box> boxes = scattered_boxes(uniform);
    const FlatBvh flat = build_bvh(boxes, 4);
    const WideBvh<W> wide = collapse<W>(flat);
    REQUIRE(wide.nodes.size() > 10);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        Ray ray{Vec3(uniform(-3, 13), uniform(-3, 13), uniform(-3, 13)),
                Vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1))};
        if (i % 7 == 0) ray.direction[i % 3] = i % 2 ? Real(0) : -Real(0);    // a slab's plane: 1/d is +-inf
        const Interval interval{i % 5 == 0 ? Real(-2) : Real(0), kInfinity};  // both forms of enter()
        const Real want = nearest_box_entry(boxes, ray, interval);
        Real best = kInfinity;
        auto leaf = [&](std::uint32_t first, std::uint32_t count, Interval& iv) {
            bool closer = false;
            for (std::uint32_t s = first; s < first + count; ++s) {
                Interval box_iv = iv;
                if (clip_to_box(boxes[flat.items[s]], ray, box_iv) && box_iv.min < best) {
                    best = box_iv.min;
                    iv.max = best;
                    closer = true;
                }
            }
            return closer;
        };
        const bool found = closest_hit(wide, WideRay<W>(ray), interval, leaf, [](std::uint32_t) {});
        CHECK(found == (want < kInfinity));
        CHECK(best == want);
        const bool any = any_hit(
            wide, WideRay<W>(ray), interval,
            [&](std::uint32_t first, std::uint32_t count, Interval& iv) {
                for (std::uint32_t s = first; s < first + count; ++s) {
                    Interval box_iv = iv;
                    if (clip_to_box(boxes[flat.items[s]], ray, box_iv)) return true;
                }
                return false;
            },
            [](std::uint32_t) {});
        CHECK(any == (want < kInfinity));
        hits += want < kInfinity;
    }
    CHECK(hits > 300);  // the rays meet boxes often enough for the comparison to mean something
    CHECK(hits < 2900);
}

// Up to eight rays from one point at a time (a packet): each ray's own nearest box.
inline void check_packet_searches() {
    Uniform uniform(31);
    const std::vector<Box> boxes = scattered_boxes(uniform);
    const FlatBvh flat = build_bvh(boxes, 4);
    const WideBvh<kPacketRays> wide = collapse<kPacketRays>(flat);
    REQUIRE(wide.nodes.size() > 10);
    int hits = 0, packets = 0;
    for (int i = 0; i < 800; ++i) {
        const Vec3 eye(uniform(-3, 13), uniform(-3, 13), uniform(-3, 13));
        const Vec3 base = Vec3(uniform(2, 8), uniform(2, 8), uniform(2, 8)) - eye;
        const double spread = i % 3 ? 0.05 : 1.5;  // neighbouring pixels, or a wide frustum
        std::vector<Ray> rays;
        for (int k = 0; k < 1 + i % kPacketRays; ++k)
            rays.push_back(
                Ray{eye, base + Vec3(uniform(-spread, spread), uniform(-spread, spread), uniform(-spread, spread))});
        const Interval interval{i % 5 == 0 ? Real(uniform(0, 4)) : Real(0), i % 7 == 0 ? Real(9) : kInfinity};
        WidePacket packet;
        if (!make_packet(rays, interval, packet)) continue;  // another octant among them
        ++packets;
        Real best[kPacketRays];
        for (Real& b : best) b = kInfinity;
        closest_hits(
            wide, packet,
            [&](std::uint32_t first, std::uint32_t count, unsigned which) {
                bool narrowed = false;
                for (; which != 0; which &= which - 1) {
                    const int k = std::countr_zero(which);
                    for (std::uint32_t s = first; s < first + count; ++s) {
                        Interval box_iv{interval.min, std::min(interval.max, best[k])};
                        if (clip_to_box(boxes[flat.items[s]], rays[std::size_t(k)], box_iv) && box_iv.min < best[k]) {
                            best[k] = box_iv.min;
                            packet.narrow(k, best[k]);
                            narrowed = true;
                        }
                    }
                }
                return narrowed;
            },
            [](std::uint32_t) {});
        for (std::size_t k = 0; k < rays.size(); ++k) {
            const Real want = nearest_box_entry(boxes, rays[k], interval);
            CAPTURE(i);
            CAPTURE(k);
            CHECK(best[k] == want);
            hits += want < kInfinity;
        }
    }
    CHECK(packets > 500);  // most packets are in one octant
    CHECK(hits > 300);     // the rays meet boxes often enough for the comparison to mean something
}

}  // namespace
}  // namespace rt::test
