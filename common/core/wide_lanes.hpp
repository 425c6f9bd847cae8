#pragma once
// W floats side by side, the lanes the wide BVH (core/wide_bvh.hpp) and the triangle blocks
// (geometry/triangle_block.hpp) compute in, and the two things the compiler's vectors do
// not spell portably: a comparison's lanes as bits, and one value in every lane.
//
// Which instructions do it is decided here and nowhere else. On x86-64 (SSE2 is in every
// one) the movemask instructions, and with AVX2 also the eight-lane shuffle that pushes a
// node's children (RTLAB_LANES_AVX2, read by core/wide_bvh.hpp). On any other machine
// (AArch64: a recent Mac), or with RTLAB_PORTABLE_LANES defined (so that x86 can test
// this path: tests/test_portable_lanes.cpp), plain lane-by-lane code, which the compiler
// turns into the machine's own vector instructions where it has them.
//
// The inline namespace RTLAB_LANES_NAMESPACE (here and around the code that calls these)
// gives each choice its own names, so that a program may build one file the portable way and
// link it with a library built the x86 way without two different bodies under one name.
#include <cstdint>
#include <cstring>

#if defined(__SSE2__) && !defined(RTLAB_PORTABLE_LANES)
#define RTLAB_LANES_X86 1
#define RTLAB_LANES_NAMESPACE lanes_x86
#if defined(__AVX2__)
#define RTLAB_LANES_AVX2 1
#endif
#include <immintrin.h>
#else
#define RTLAB_LANES_NAMESPACE lanes_portable
#endif

namespace rt {

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

#if defined(RTLAB_LANES_X86)
inline namespace RTLAB_LANES_NAMESPACE {

// Bit c set where lane c of a comparison's result is true.
inline unsigned lane_mask(FloatLanes<4>::type m) {
    return unsigned(_mm_movemask_ps(__m128(m)));
}
inline unsigned lane_mask(const FloatLanes<8>::type& m) {
#ifdef __AVX__
    return unsigned(_mm256_movemask_ps(__m256(m)));
#else
    FloatLanes<4>::type half[2];
    std::memcpy(half, &m, sizeof half);
    return lane_mask(half[0]) | lane_mask(half[1]) << 4;
#endif
}

// v = x in every lane. (An out-parameter: a 32-byte vector returned by value draws GCC's
// ABI warning in builds without AVX.)
template <class F>
inline void splat(F& v, float x) {
    if constexpr (sizeof(F) == 16) {
        v = F(_mm_set1_ps(x));
    } else {
#ifdef __AVX__
        v = F(_mm256_set1_ps(x));
#else
        const __m128 half = _mm_set1_ps(x);
        std::memcpy(&v, &half, 16);
        std::memcpy(reinterpret_cast<char*>(&v) + 16, &half, 16);
#endif
    }
}

}  // namespace RTLAB_LANES_NAMESPACE
#else
inline namespace RTLAB_LANES_NAMESPACE {

// Bit c set where lane c of a comparison's result is true (all ones: a negative integer).
template <class F>
inline unsigned lane_mask(const F& m) {
    constexpr int kW = int(sizeof(F) / sizeof(float));
    using Bits = decltype(m < m);  // W 32-bit integers
    const Bits b = Bits(m);
    unsigned mask = 0;
    for (int c = 0; c < kW; ++c) mask |= unsigned(b[c] < 0) << c;
    return mask;
}

// v = x in every lane, -0 kept (a sum with a zero vector would make it +0).
template <class F>
inline void splat(F& v, float x) {
    for (int c = 0; c < int(sizeof(F) / sizeof(float)); ++c) v[c] = x;
}

}  // namespace RTLAB_LANES_NAMESPACE
#endif

}  // namespace rt
