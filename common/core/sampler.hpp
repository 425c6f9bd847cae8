#pragma once
// Per-pixel random numbers in named, independent dimensions. Each (seed, pixel, dimension)
// owns its own PCG stream, so what a pixel draws never depends on which thread renders it
// or in what order (images are bit-identical for any thread count), and drawing more
// numbers in one dimension (say, more light samples) never shifts another (the lens).
#include "core/real.hpp"

#include <pcg_random.hpp>

#include <array>
#include <cstddef>
#include <cstdint>

namespace rt {

// What a random number is for. Each distribution chapter stratifies its own dimension in
// its own strata and shuffles the strata against the others (the course's Fisher-Yates
// step); keeping them apart here is what makes that possible without new signatures.
enum class Dimension : std::uint8_t { pixel, lens, time, light, glossy, other };
inline constexpr std::size_t kDimensions = 6;

class Sampler {
public:
    Sampler(std::uint64_t seed, std::uint64_t pixel_index) {
        for (std::size_t d = 0; d < kDimensions; ++d) streams_[d] = pcg32(seed, pixel_index * kDimensions + d);
    }

    // Starts sample `index` of this pixel's samples (0, 1, ..., spp - 1).
    void start_sample(int index) { sample_ = index; }
    int sample_index() const { return sample_; }

    // Uniform in [0, 1), from dimension d's own stream.
    Real get1(Dimension d) { return to_unit(streams_[std::size_t(d)]); }
    Vec2 get2(Dimension d) {
        const Real a = get1(d);
        return Vec2(a, get1(d));
    }

private:
    static Real to_unit(pcg32& rng) {
        // 24 (or 53) random bits: exactly representable, never rounds up to 1.
        if constexpr (sizeof(Real) == sizeof(float))
            return Real(rng() >> 8) * Real(0x1p-24);
        else {
            // Two statements: the operands of one expression would be drawn in an order
            // the compiler picks.
            const std::uint64_t high = rng();
            const std::uint64_t low = rng();
            return Real((high << 21) ^ low) * Real(0x1p-53);
        }
    }

    std::array<pcg32, kDimensions> streams_;
    int sample_ = 0;
};

}  // namespace rt
