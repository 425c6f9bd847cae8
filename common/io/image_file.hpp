#pragma once
// Image files: PNG (8-bit sRGB, through stb) and PFM (linear float).
#include "render/image.hpp"

#include <string>

namespace rt {

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
