#pragma once
// Rounding a Real to the float on either side of it, for structures that store boxes in
// float (core/flat_bvh.hpp, core/wide_bvh.hpp) and must round them outwards, never inwards.
#include "core/opaque.hpp"
#include "core/real.hpp"

#include <bit>
#include <cstdint>

namespace rt {

// x rounded to the nearest float, as a Real. Written out because GCC 12.2 (Debian 12's)
// miscompiles the plain `Real(float(x))` when it vectorises two or more of them side by
// side: the narrowing and the widening are folded away and x comes back unrounded (wrong
// code from -O2 on; tests/test_common.cpp checks this). opaque() hides the float from the folding.
inline Real round_to_float(Real x) {
    float f = float(x);
    opaque(f);
    return Real(f);
}

// Rounding a Real to a float below or above it. Stepping the bits by one is nextafter for
// the finite floats that can need it (an infinity converts exactly), without a libm call
// in the per-ray set-up.
inline float float_below(Real x) {
    const float f = float(x);
    if (!(Real(f) > x)) return f;
    const auto b = std::bit_cast<std::uint32_t>(f);
    return f > 0 ? std::bit_cast<float>(b - 1) : f < 0 ? std::bit_cast<float>(b + 1) : -0x1p-149f;
}
inline float float_above(Real x) {
    return -float_below(-x);
}

// float_below and float_above of a point's three coordinates at once, as four-lane vectors
// (the per-ray set-up of the wide BVH: branches there cost more than the arithmetic). Where
// the conversion rounded the wrong way, the bits step by one towards the value: down for
// below, up for above, which is -1 or +1 on the bits by the sign (the zero that can need a
// step has the sign the step needs: -0 below a tiny negative value, +0 above a tiny positive one).
inline void float_bounds(const Vec3& p, float (&below)[3], float (&above)[3]) {
    if constexpr (sizeof(Real) == sizeof(float)) {
        for (int a = 0; a < 3; ++a) below[a] = above[a] = float(p[a]);
    } else {
        using D4 = double __attribute__((vector_size(32)));
        using F4 = float __attribute__((vector_size(16)));
        using I4 = std::int32_t __attribute__((vector_size(16)));
        const D4 x = {double(p.x), double(p.y), double(p.z), 0};
        const F4 f = __builtin_convertvector(x, F4);
        const D4 back = __builtin_convertvector(f, D4);
        using I8 = std::int32_t __attribute__((vector_size(32)));
        const I8 up8 = I8(back > x), down8 = I8(back < x);  // each lane's mask is two equal halves
        const I4 up = __builtin_shufflevector(up8, up8, 0, 2, 4, 6);
        const I4 down = __builtin_shufflevector(down8, down8, 0, 2, 4, 6);
        const I4 bits = I4(f), step = (bits >> 31) | 1;  // -1 for a negative float, +1 otherwise
        const F4 lo = F4(bits - (step & up)), hi = F4(bits + (step & down));
        for (int a = 0; a < 3; ++a) {
            below[a] = lo[a];
            above[a] = hi[a];
        }
    }
}

}  // namespace rt
