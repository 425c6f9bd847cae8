#include "render/image.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>

namespace rt {

float linear_to_srgb(float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

namespace {

// The 8-bit codes as a table over the floats of [0, 1), in buckets of 2^15 consecutive bit
// patterns (non-negative floats order as their bits): each bucket holds the code of its first
// float and the least float of the next code. A bucket is narrower than one code's run of
// floats everywhere (at most 2e-3 wide near 1, where a code spans 9e-3; 1e-6 in the linear toe,
// where it spans 3e-4), so a float's code is its bucket's, or one more.
struct Srgb8Table {
    static constexpr int kShift = 15;
    static constexpr std::size_t kBuckets = std::bit_cast<std::uint32_t>(1.0f) >> kShift;
    std::array<std::uint8_t, kBuckets> first{};
    std::array<float, 256> next{};  // next[k]: the least float of code k + 1 (infinite for k = 255)

    static int code(float x) { return int(std::lround(255.0f * linear_to_srgb(x))); }

    Srgb8Table() {
        // The least float of each code, by bisection on the bit patterns (code rises with x).
        for (int k = 1; k <= 255; ++k) {
            std::uint32_t lo = 0, hi = std::bit_cast<std::uint32_t>(1.0f);  // code(lo) < k <= code(hi)
            while (hi - lo > 1) {
                const std::uint32_t mid = lo + (hi - lo) / 2;
                (code(std::bit_cast<float>(mid)) >= k ? hi : lo) = mid;
            }
            next[std::size_t(k - 1)] = std::bit_cast<float>(hi);
        }
        next[255] = std::numeric_limits<float>::infinity();
        for (std::size_t b = 0; b < kBuckets; ++b)
            first[b] = std::uint8_t(code(std::bit_cast<float>(std::uint32_t(b << kShift))));
    }

    // The code of one value. Clamped to [0, 1] first (NaN to 0), without a branch: a picture's
    // channels go both ways at every edge. 1 falls into the last bucket, whose code is 255
    // or whose next code is.
    std::uint8_t operator()(float linear) const {
        const float x = linear > 0 ? (linear < 1 ? linear : 1.0f) : 0.0f;
        const std::uint8_t base = first[std::min(std::size_t(std::bit_cast<std::uint32_t>(x) >> kShift), kBuckets - 1)];
        return std::uint8_t(base + (x >= next[base]));
    }
};

const Srgb8Table& srgb8_table() {
    static const Srgb8Table table;
    return table;
}

}  // namespace

std::uint8_t linear_to_srgb8(float linear) {
    return srgb8_table()(linear);
}

void linear_to_srgb8(std::span<const Color> pixels, std::uint8_t* codes) {
    // The table once, not a guarded static per channel: half of writing a PNG was spent here.
    const Srgb8Table& table = srgb8_table();
    for (const Color& p : pixels)
        for (int c = 0; c < 3; ++c) *codes++ = table(p[c]);
}

float srgb_to_linear(float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

}  // namespace rt
