#include "app/explore_frame.hpp"

#include <stb_image_write.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace rt {

namespace {

// linear_to_srgb per channel costs a pow(); a frame has 700,000 channels. A table of 4096
// steps of the linear value is within one 8-bit step of it everywhere.
constexpr int kSteps = 4096;
const std::array<std::uint8_t, kSteps + 1>& srgb_table() {
    static const auto table = [] {
        std::array<std::uint8_t, kSteps + 1> t{};
        for (int i = 0; i <= kSteps; ++i)
            t[std::size_t(i)] = std::uint8_t(std::lround(255.0f * linear_to_srgb(float(i) / kSteps)));
        return t;
    }();
    return table;
}

std::uint8_t encode(double linear) {
    // NaN goes to 0 with the clamp's comparisons written this way round.
    const double c = linear > 0 ? (linear < 1 ? linear : 1) : 0;
    return srgb_table()[std::size_t(c * kSteps + 0.5)];
}

void append(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
}

}  // namespace

void to_rgb(const Image& image, std::vector<std::uint8_t>& rgb) {
    rgb.resize(image.pixels.size() * 3);
    std::uint8_t* out = rgb.data();
    for (const Color& p : image.pixels) {
        *out++ = encode(p.r);
        *out++ = encode(p.g);
        *out++ = encode(p.b);
    }
}

void accumulate_to_rgb(const Image& pass, std::vector<double>& sum, int samples, std::vector<std::uint8_t>& rgb) {
    const double scale = 1.0 / samples;
    rgb.resize(pass.pixels.size() * 3);
    double* s = sum.data();
    std::uint8_t* out = rgb.data();
    for (const Color& p : pass.pixels) {
        s[0] += double(p.r);
        s[1] += double(p.g);
        s[2] += double(p.b);
        *out++ = encode(s[0] * scale);
        *out++ = encode(s[1] * scale);
        *out++ = encode(s[2] * scale);
        s += 3;
    }
}

const char* mime_type(FrameFormat format) {
    switch (format) {
        case FrameFormat::png:
            return "image/png";
        case FrameFormat::jpeg:
            return "image/jpeg";
        case FrameFormat::rgb:
        case FrameFormat::rgba:
            break;
    }
    return "application/octet-stream";
}

std::string encode_frame(const ExploreFrame& f, FrameFormat format) {
    std::string out;
    bool ok = true;
    switch (format) {
        case FrameFormat::rgb:
            out.assign(f.rgb.begin(), f.rgb.end());
            break;
        case FrameFormat::rgba:
            out.resize(f.rgb.size() / 3 * 4);
            for (std::size_t i = 0, n = f.rgb.size() / 3; i < n; ++i) {
                for (std::size_t c = 0; c < 3; ++c) out[4 * i + c] = char(f.rgb[3 * i + c]);
                out[4 * i + 3] = char(255);
            }
            break;
        case FrameFormat::png:
            ok = stbi_write_png_to_func(append, &out, f.width, f.height, 3, f.rgb.data(), f.width * 3) != 0;
            break;
        case FrameFormat::jpeg:
            ok = stbi_write_jpg_to_func(append, &out, f.width, f.height, 3, f.rgb.data(), 90) != 0;
            break;
    }
    if (!ok) throw std::runtime_error("cannot encode a frame");
    return out;
}

}  // namespace rt
