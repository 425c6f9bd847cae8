#pragma once
// A linear-RGB float image, row 0 at the top (as files store it).
#include "core/real.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace rt {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<Color> pixels;  // row-major, top row first

    Image() = default;
    Image(int w, int h) : width(w), height(h), pixels(std::size_t(w) * std::size_t(h), Color(0)) {}

    Color& at(int x, int y) { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    const Color& at(int x, int y) const { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};

// sRGB transfer function, per channel; inputs are clamped to [0, 1].
float linear_to_srgb(float linear);
float srgb_to_linear(float encoded);

// The 8-bit sRGB code of a linear value: exactly lround(255 * linear_to_srgb(linear)), read
// from a table instead of through pow() (writing an image spent most of its time there).
// NaN gives 0.
std::uint8_t linear_to_srgb8(float linear);
// The same for every channel of `pixels`, three codes a pixel into `codes`.
void linear_to_srgb8(std::span<const Color> pixels, std::uint8_t* codes);

}  // namespace rt
