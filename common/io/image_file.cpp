#include "io/image_file.hpp"

#include <spng.h>
#include <stb_image.h>

#include "core/text.hpp"
#include "io/input_file.hpp"

#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace rt {

namespace {

// The temporary file being written, for the signal handler: a fixed buffer, since a
// handler may not allocate.
char g_temporary[4096];
volatile std::sig_atomic_t g_writing = 0;

extern "C" void on_interrupt(int signal) {
    if (g_writing) ::unlink(g_temporary);
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

}  // namespace

void remove_temporaries_on_interrupt() {
    std::signal(SIGINT, on_interrupt);
    std::signal(SIGTERM, on_interrupt);
}

void write_file_atomically(const std::string& path, const std::string& bytes) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    if (target.has_parent_path()) {
        std::error_code ec;
        fs::create_directories(target.parent_path(), ec);
        if (ec)
            throw std::runtime_error("cannot create directory " + target.parent_path().string() + ": " + ec.message());
    }
    // The temporary lives in the target's directory so that rename() stays atomic.
    const std::string tmp = path + ".tmp." + std::to_string(::getpid());
    if (tmp.size() >= sizeof g_temporary) throw std::runtime_error("cannot write " + path + ": path too long");
    std::memcpy(g_temporary, tmp.c_str(), tmp.size() + 1);
    g_writing = 1;
    const auto fail = [&](const std::string& why) {
        std::remove(tmp.c_str());
        g_writing = 0;
        throw std::runtime_error("cannot write " + path + ": " + why);
    };
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) fail(std::strerror(errno));
        out.write(bytes.data(), std::streamsize(bytes.size()));
        out.flush();
        if (!out) fail("write failed");
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) fail(std::strerror(errno));
    g_writing = 0;
}

namespace {

constexpr int kPngCompressionLevel = 1;
constexpr int kPngFilters = SPNG_FILTER_CHOICE_NONE;

}  // namespace

std::string encode_png(const Image& image) {
    std::vector<unsigned char> bytes(image.pixels.size() * 3);
    linear_to_srgb8(image.pixels, bytes.data());
    // zlib's fastest level with no row filter: stb's encoder (every filter tried on every row,
    // its own deflate) took 0.2 s for 1280 x 720, seven times this, for a file no smaller
    // (bench/png.cpp measures both).
    const std::unique_ptr<spng_ctx, void (*)(spng_ctx*)> ctx(spng_ctx_new(SPNG_CTX_ENCODER), spng_ctx_free);
    spng_ihdr header{};
    header.width = std::uint32_t(image.width);
    header.height = std::uint32_t(image.height);
    header.bit_depth = 8;
    header.color_type = SPNG_COLOR_TYPE_TRUECOLOR;
    int error = ctx ? 0 : SPNG_EMEM;
    if (!error) error = spng_set_option(ctx.get(), SPNG_ENCODE_TO_BUFFER, 1);
    if (!error) error = spng_set_option(ctx.get(), SPNG_IMG_COMPRESSION_LEVEL, kPngCompressionLevel);
    if (!error) error = spng_set_option(ctx.get(), SPNG_FILTER_CHOICE, kPngFilters);
    if (!error) error = spng_set_ihdr(ctx.get(), &header);
    if (!error) error = spng_encode_image(ctx.get(), bytes.data(), bytes.size(), SPNG_FMT_PNG, SPNG_ENCODE_FINALIZE);
    std::size_t size = 0;
    void* buffer = error ? nullptr : spng_get_png_buffer(ctx.get(), &size, &error);
    if (!buffer) throw std::runtime_error(std::string("cannot encode PNG: ") + spng_strerror(error));
    std::string encoded(static_cast<const char*>(buffer), size);
    std::free(buffer);
    return encoded;
}

void write_png(const Image& image, const std::string& path) {
    write_file_atomically(path, encode_png(image));
}

void write_pfm(const Image& image, const std::string& path) {
    std::ostringstream out;
    // Negative scale: little-endian. PFM stores rows bottom to top.
    out << "PF\n" << image.width << ' ' << image.height << "\n-1.0\n";
    std::string body(image.pixels.size() * 3 * sizeof(float), '\0');
    char* dst = body.data();
    for (int y = image.height - 1; y >= 0; --y)
        for (int x = 0; x < image.width; ++x) {
            const Color& c = image.at(x, y);
            const float rgb[3] = {c.r, c.g, c.b};
            std::memcpy(dst, rgb, sizeof rgb);
            dst += sizeof rgb;
        }
    write_file_atomically(path, out.str() + body);
}

bool is_image_path(const std::string& path) {
    // A bare ".png" names no file: it is a hidden file without an extension.
    const std::filesystem::path extension = std::filesystem::path(path).extension();
    return extension == ".png" || extension == ".pfm";
}

void write_image(const Image& image, const std::string& path) {
    if (!is_image_path(path)) throw std::runtime_error("output " + path + ": extension must be .png or .pfm");
    if (path.ends_with(".png")) return write_png(image, path);
    return write_pfm(image, path);
}

namespace {

[[noreturn]] void refuse(const std::string& name, const std::string& why) {
    throw std::runtime_error(one_line("cannot read image " + name + ": " + why));
}

void check_size(const std::string& name, double w, double h) {
    for (const double side : {w, h})
        if (!limits::contains(limits::image_side, side)) refuse(name, limits::refuse(limits::image_side, side));
    if (!limits::contains(limits::image_pixels, w * h)) refuse(name, limits::refuse(limits::image_pixels, w * h));
}

constexpr char kPngSignature[] = "\x89PNG\r\n\x1a\n";

}  // namespace

Image decode_png(const std::string& bytes, const std::string& name) {
    // Only PNG reaches stb: its other decoders are not what this function promises.
    if (bytes.compare(0, 8, kPngSignature, 8) != 0) refuse(name, "not a PNG file");
    if (bytes.size() > std::size_t(std::numeric_limits<int>::max())) refuse(name, "file too large");
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    const int size = int(bytes.size());
    // The size, from the header chunk that must come first, before stb allocates anything
    // (stb's own refusal of a huge image says only "unknown image type").
    if (bytes.size() >= 24 && bytes.compare(12, 4, "IHDR") == 0) {
        const auto be32 = [&](std::size_t at) {
            double v = 0;
            for (std::size_t k = 0; k < 4; ++k) v = v * 256 + static_cast<unsigned char>(bytes[at + k]);
            return v;
        };
        check_size(name, be32(16), be32(20));
    }
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(data, size, &w, &h, &channels)) refuse(name, stbi_failure_reason());
    check_size(name, w, h);
    unsigned char* pixels = stbi_load_from_memory(data, size, &w, &h, &channels, 3);
    if (!pixels) refuse(name, stbi_failure_reason());
    Image image(w, h);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) image.pixels[i][c] = srgb_to_linear(pixels[3 * i + std::size_t(c)] / 255.0f);
    stbi_image_free(pixels);
    return image;
}

Image decode_pfm(const std::string& bytes, const std::string& name) {
    // The header: "PF", width, height, scale (negative: little-endian), each after white
    // space, then exactly one white-space byte before the pixels.
    std::size_t i = 0;
    const auto token = [&] {
        while (i < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[i]))) ++i;
        const std::size_t begin = i;
        while (i < bytes.size() && i - begin < 32 && !std::isspace(static_cast<unsigned char>(bytes[i]))) ++i;
        return bytes.substr(begin, i - begin);
    };
    const std::string magic = token(), ws = token(), hs = token(), scale = token();
    const auto whole = [](const std::string& s) {
        return !s.empty() && s.size() <= 6 && s.find_first_not_of("0123456789") == std::string::npos ? std::stod(s)
                                                                                                     : -1.0;
    };
    const double w = whole(ws), h = whole(hs);
    if (magic != "PF" || w < 0 || h < 0 || scale.empty() || scale[0] != '-' || i >= bytes.size())
        refuse(name, "not a little-endian colour PFM");
    check_size(name, w, h);
    ++i;  // the single white-space byte after the header
    const std::size_t count = std::size_t(w) * std::size_t(h) * 3;
    if (bytes.size() - i != count * sizeof(float))
        refuse(name, "holds " + std::to_string(bytes.size() - i) + " bytes of pixels, not " +
                         std::to_string(count * sizeof(float)) + " for " + ws + "x" + hs);
    Image image{int(w), int(h)};
    const char* src = bytes.data() + i;
    for (int y = image.height - 1; y >= 0; --y)  // PFM stores rows bottom to top
        for (int x = 0; x < image.width; ++x) {
            float rgb[3];
            std::memcpy(rgb, src, sizeof rgb);
            src += sizeof rgb;
            if (!std::isfinite(rgb[0]) || !std::isfinite(rgb[1]) || !std::isfinite(rgb[2]))
                refuse(name, "pixel " + std::to_string(x) + "," + std::to_string(y) + " is not finite");
            image.at(x, y) = Color(rgb[0], rgb[1], rgb[2]);
        }
    return image;
}

Image decode_image(const std::string& bytes, const std::string& name) {
    return bytes.compare(0, 2, "PF") == 0 ? decode_pfm(bytes, name) : decode_png(bytes, name);
}

namespace {

std::string image_bytes(const std::string& path) {
    try {
        return read_input_file(path, "image", limits::image_file_bytes);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(std::string("cannot read ") + e.what());  // "cannot read image PATH: ..."
    }
}

}  // namespace

Image read_png(const std::string& path) {
    return decode_png(image_bytes(path), path);
}
Image read_pfm(const std::string& path) {
    return decode_pfm(image_bytes(path), path);
}
Image read_image(const std::string& path) {
    return decode_image(image_bytes(path), path);
}

}  // namespace rt
