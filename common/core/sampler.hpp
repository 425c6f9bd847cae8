#pragma once
// Per-pixel random numbers in named, independent dimensions. Each (seed, pixel, dimension)
// owns its own PCG stream, so what a pixel draws never depends on which thread renders it
// or in what order (images are bit-identical for any thread count), and drawing more
// numbers in one dimension (say, more light samples) never shifts another (the lens).
#include "core/names.hpp"
#include "core/real.hpp"

#include <pcg_random.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace rt {

// What a random number is for. Each distribution chapter stratifies its own dimension in
// its own strata and shuffles the strata against the others (the course's Fisher-Yates
// step); keeping them apart here is what makes that possible without new signatures.
enum class Dimension : std::uint8_t { pixel, lens, time, light, glossy, other };
inline constexpr auto kDimensionNames = names_of<Dimension>({"pixel", "lens", "time", "light", "glossy", "other"});
inline constexpr std::size_t kDimensions = kDimensionNames.size();

// How a pixel's samples divide each dimension (book §14.2, §15.2): not at all (random),
// into strata sampled at their centres (regular), or at a random place in each (jittered).
enum class Strata : std::uint8_t { none, centres, jittered };

// Exercise 15.1: put `order` into a uniformly random order (Fisher-Yates), drawing whole
// numbers from `random`: random(b) is uniform in 0, 1, ..., b - 1.
void fisher_yates(std::vector<std::uint32_t>& order, pcg32& random);

class Sampler {
public:
    Sampler(std::uint64_t seed, std::uint64_t pixel_index) : seed_(seed) { start_pixel(pixel_index); }

    // Moves to another pixel: its numbers are the same as a new Sampler(seed, pixel_index)
    // would give. A stream is seeded at its dimension's first draw, not here: a camera ray
    // through the pixel's centre draws nothing, and seeding all six streams of every pixel
    // cost more than the rest of the pixel's set-up together. One sampler serves a whole
    // tile, so the strata orders keep their memory from pixel to pixel.
    void start_pixel(std::uint64_t pixel_index) {
        pixel_ = pixel_index;
        seeded_ = 0;
        ordered_ = 0;
    }

    // This pixel takes `count` samples, each dimension divided into `count` strata (a line)
    // or side x side of them (a square; side = 0 when count is not a square), as `strata` says.
    void set_strata(int count, int side, Strata strata) {
        count_ = count;
        side_ = side;
        strata_ = side > 0 || strata == Strata::none ? strata : Strata::none;
        ordered_ = 0;
    }
    int count() const { return count_; }
    int side() const { return side_; }
    Strata strata() const { return strata_; }

    // Starts sample `index` of this pixel's samples (0, 1, ..., count - 1).
    void start_sample(int index) {
        sample_ = index;
        used_ = 0;
    }
    int sample_index() const { return sample_; }

    // Uniform in [0, 1), from dimension d's own stream.
    Real get1(Dimension d) {
        ++draws_[std::size_t(d)];
        return to_unit(stream(d));
    }
    Vec2 get2(Dimension d) {
        const Real a = get1(d);
        return Vec2(a, get1(d));
    }

    // Which of the pixel's strata the current sample takes in dimension d. The pixel's own
    // dimension goes through its strata in order; every other one in an order of its own,
    // shuffled once per pixel, so that no dimension's stratum follows another's (book §15.2).
    int stratum(Dimension d) {
        if (d == Dimension::pixel) return sample_;
        std::vector<std::uint32_t>& order = orders_[std::size_t(d)];
        if (!take(ordered_, d)) {
            order.resize(std::size_t(count_));
            std::iota(order.begin(), order.end(), 0u);
            fisher_yates(order, stream(d));
        }
        return int(order[std::size_t(sample_)]);
    }

    // True for the current sample's first request of a stratified point in dimension d, and
    // false after: only that one takes the sample's stratum. A second request in the same
    // sample (a second glossy bounce, a second area light) that took the same stratum would
    // be tied to the first, and where the two multiply along a path the average is biased.
    bool take_stratum(Dimension d) { return !take(used_, d) && strata_ != Strata::none; }

    // How many numbers each dimension has drawn since this sampler was made, over every
    // pixel it served (--stats: what a scene's effects cost).
    const std::array<std::uint64_t, kDimensions>& draws() const { return draws_; }

private:
    // Sets dimension d's bit in `bits` and says whether it was set already.
    static bool take(std::uint8_t& bits, Dimension d) {
        const auto bit = std::uint8_t(1u << unsigned(d));
        const bool was = bits & bit;
        bits |= bit;
        return was;
    }
    // Each (seed, pixel, dimension) owns its own PCG stream.
    pcg32& stream(Dimension d) {
        const auto k = std::size_t(d);
        if (!take(seeded_, d)) streams_[k] = pcg32(seed_, pixel_ * kDimensions + k);
        return streams_[k];
    }
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

    static_assert(kDimensions <= 8, "one bit per dimension in seeded_, ordered_ and used_");
    std::uint64_t seed_;
    std::uint64_t pixel_ = 0;
    std::array<pcg32, kDimensions> streams_;
    std::array<std::vector<std::uint32_t>, kDimensions> orders_;
    std::array<std::uint64_t, kDimensions> draws_{};
    std::uint8_t seeded_ = 0;   // the dimensions whose stream this pixel has seeded
    std::uint8_t ordered_ = 0;  // the dimensions whose strata order this pixel has shuffled
    std::uint8_t used_ = 0;     // a stratified point taken in this sample
    int sample_ = 0;
    int count_ = 1;
    int side_ = 1;
    Strata strata_ = Strata::none;
};

}  // namespace rt
