#pragma once
// Per-pixel random numbers. Each pixel owns a PCG stream chosen by (seed, pixel index), so
// what a pixel draws never depends on which thread renders it or in what order: images
// are bit-identical for any thread count.
#include "common/real.hpp"

#include <pcg_random.hpp>

#include <cstdint>

namespace rt {

class Sampler {
public:
    Sampler(std::uint64_t seed, std::uint64_t pixel_index) : rng_(seed, pixel_index) {}

    // Uniform in [0, 1).
    Real uniform() {
        // 24 (or 53) random bits: exactly representable, never rounds up to 1.
        if constexpr (sizeof(Real) == sizeof(float))
            return Real(rng_() >> 8) * Real(0x1p-24);
        else
            return Real((std::uint64_t(rng_()) << 21) ^ std::uint64_t(rng_())) * Real(0x1p-53);
    }
    Vec2 uniform2() {
        const Real a = uniform();
        return Vec2(a, uniform());
    }

private:
    pcg32 rng_;
};

}  // namespace rt
