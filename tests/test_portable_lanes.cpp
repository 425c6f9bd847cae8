// The wide BVH's portable lanes (core/wide_lanes.hpp), the path an AArch64 build takes,
// compiled and tested on x86 too: this file asks for it with RTLAB_PORTABLE_LANES, and its
// names (rt::lanes_portable) keep it apart from the library's x86 code it links with.
#define RTLAB_PORTABLE_LANES
#include "core/wide_bvh.hpp"
#include "support/box_searches.hpp"

#include <doctest/doctest.h>

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
    rt::test::check_searches<4>();
    rt::test::check_searches<8>();
}

TEST_CASE("portable lanes: a packet's search finds each ray the nearest box brute force finds") {
    rt::test::check_packet_searches();
}

}  // TEST_SUITE("common")
