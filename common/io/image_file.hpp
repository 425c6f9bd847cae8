#pragma once
// Image files: PNG (8-bit sRGB; written through libspng, read through stb) and PFM (linear
// float).
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
// The bytes of the PNG file write_png writes. Throws std::runtime_error.
std::string encode_png(const Image& image);

// Reads an 8-bit PNG (any channel count) into linear RGB. Throws std::runtime_error.
Image read_png(const std::string& path);
// Reads a colour PFM ("PF"); every value must be finite. Throws std::runtime_error.
Image read_pfm(const std::string& path);
// Either, by the file's first bytes. Files past limits::image_file_bytes and images past
// limits::image_pixels are refused before they are decoded.
Image read_image(const std::string& path);
// The same, from the bytes of a file; `name` is what messages call it.
Image decode_png(const std::string& bytes, const std::string& name);
Image decode_pfm(const std::string& bytes, const std::string& name);
Image decode_image(const std::string& bytes, const std::string& name);

// Writes bytes to path atomically (temporary + rename). Throws std::runtime_error.
void write_file_atomically(const std::string& path, const std::string& bytes);

// From now on SIGINT and SIGTERM remove the temporary file a write may have in progress
// before the process ends as the signal says (exit status 128 + signal in a shell): an
// interrupted run leaves neither an image nor a temporary behind.
void remove_temporaries_on_interrupt();

}  // namespace rt
