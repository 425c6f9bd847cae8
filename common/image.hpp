#pragma once
// A linear-RGB float image, row 0 at the top (as files store it).
#include "common/real.hpp"

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
    const Color& at(int x, int y) const {
        return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
};

// sRGB transfer function, per channel; inputs are clamped to [0, 1].
float linear_to_srgb(float linear);
float srgb_to_linear(float encoded);

// True for the paths the writers accept: ending in .png or .pfm.
bool is_image_path(const std::string& path);

// Writers choose the format from the extension (.png: 8-bit sRGB, .pfm: linear float).
// They write a temporary file next to the target and rename it, so a crash or a full disk
// never leaves half an image under the final name. They throw std::runtime_error.
void write_image(const Image& image, const std::string& path);
void write_png(const Image& image, const std::string& path);
void write_pfm(const Image& image, const std::string& path);

// Reads an 8-bit PNG (any channel count) into linear RGB. Throws std::runtime_error.
Image read_png(const std::string& path);
// Reads a colour PFM ("PF"). Throws std::runtime_error.
Image read_pfm(const std::string& path);

// Writes bytes to path atomically (temporary + rename). Throws std::runtime_error.
void write_file_atomically(const std::string& path, const std::string& bytes);

}  // namespace rt
