// The wide BVH's portable lanes (core/wide_lanes.hpp), the path an AArch64 build takes,
// compiled and tested on x86 too: this file asks for it with RTLAB_PORTABLE_LANES, and its
// names (rt::lanes_portable) keep it apart from the library's x86 code it links with.
#define RTLAB_PORTABLE_LANES
#include "core/wide_bvh.hpp"
#include "support/packet_boxes.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace rt;

#ifdef RTLAB_LANES_X86
#error "this file must compile the portable lanes"
#endif

namespace {

template <int W>
void check_lane_masks() {
    using F = typename FloatLanes<W>::type;
    for (unsigned want = 0; want < 1u << W; ++want) {
        F v;
        for (int c = 0; c < W; ++c) v[c] = want >> c & 1 ? 1.0f : -1.0f;
        const F zero{};
        CHECK(lane_mask(F(v > zero)) == want);
    }
}

// The entry distance of the nearest box the ray meets within the interval, by testing each.
Real nearest_entry(const std::vector<Box>& boxes, const Ray& ray, Interval interval) {
    Real best = kInfinity;
    for (const Box& box : boxes) {
        Interval iv = interval;
        if (clip_to_box(box, ray, iv) && iv.min < best) best = iv.min;
    }
    return best;
}

template <int W>
void check_searches() {
    std::mt19937 rng(29);
    auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * std::ldexp(double(rng()), -32); };
    std::vector<Box> boxes(600);
    for (Box& b : boxes) {
        const Vec3 c(uniform(0, 10), uniform(0, 10), uniform(0, 10));
        const Vec3 h(uniform(0.01, 0.4), uniform(0.01, 0.4), uniform(0.01, 0.4));
        b.min = c - h;
        b.max = c + h;
    }
    const FlatBvh flat = build_bvh(boxes, 4);
    const WideBvh<W> wide = collapse<W>(flat);
    REQUIRE(wide.nodes.size() > 10);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        Ray ray{Vec3(uniform(-3, 13), uniform(-3, 13), uniform(-3, 13)),
                Vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1))};
        if (i % 7 == 0) ray.direction[i % 3] = i % 2 ? Real(0) : -Real(0);    // a slab's plane: 1/d is +-inf
        const Interval interval{i % 5 == 0 ? Real(-2) : Real(0), kInfinity};  // both forms of enter()
        const Real want = nearest_entry(boxes, ray, interval);
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

}  // namespace

TEST_SUITE("common") {

TEST_CASE("portable lanes: a comparison's lanes as bits, for every pattern of 4 and of 8") {
    check_lane_masks<4>();
    check_lane_masks<8>();
}

TEST_CASE("portable lanes: splat puts the value in every lane, the sign of zero kept") {
    FloatLanes<8>::type v;
    splat(v, -0.0f);
    for (int c = 0; c < 8; ++c) CHECK(std::signbit(v[c]));
    splat(v, 3.5f);
    for (int c = 0; c < 8; ++c) CHECK(float(v[c]) == 3.5f);
}

TEST_CASE("portable lanes: the wide BVH's searches find the nearest box brute force finds") {
    check_searches<4>();
    check_searches<8>();
}

TEST_CASE("portable lanes: a packet's search finds each ray the nearest box brute force finds") {
    rt::test::check_packet_searches();
}

}  // TEST_SUITE("common")
