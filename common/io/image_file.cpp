#include "io/image_file.hpp"

#include <stb_image.h>
#include <stb_image_write.h>

#include <unistd.h>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rt {

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
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
        out.write(bytes.data(), std::streamsize(bytes.size()));
        out.flush();
        if (!out) {
            std::remove(tmp.c_str());
            throw std::runtime_error("cannot write " + path + ": write failed");
        }
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        const std::string why = std::strerror(errno);
        std::remove(tmp.c_str());
        throw std::runtime_error("cannot write " + path + ": " + why);
    }
}

namespace {

void append_bytes(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
}

}  // namespace

void write_png(const Image& image, const std::string& path) {
    std::vector<unsigned char> bytes(image.pixels.size() * 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            bytes[3 * i + std::size_t(c)] =
                static_cast<unsigned char>(std::lround(255.0f * linear_to_srgb(image.pixels[i][c])));
    std::string encoded;
    if (!stbi_write_png_to_func(append_bytes, &encoded, image.width, image.height, 3, bytes.data(), image.width * 3))
        throw std::runtime_error("cannot encode PNG for " + path);
    write_file_atomically(path, encoded);
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
    // A bare ".png" names no file.
    return path.size() > 4 && (path.ends_with(".png") || path.ends_with(".pfm"));
}

void write_image(const Image& image, const std::string& path) {
    if (!is_image_path(path)) throw std::runtime_error("output " + path + ": extension must be .png or .pfm");
    if (path.ends_with(".png")) return write_png(image, path);
    return write_pfm(image, path);
}

Image read_png(const std::string& path) {
    int w = 0, h = 0, channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &channels, 3);
    if (!data) throw std::runtime_error("cannot read image " + path + ": " + stbi_failure_reason());
    Image image(w, h);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) image.pixels[i][c] = srgb_to_linear(data[3 * i + std::size_t(c)] / 255.0f);
    stbi_image_free(data);
    return image;
}

Image read_pfm(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read image " + path + ": " + std::strerror(errno));
    std::string magic;
    int w = 0, h = 0;
    double scale = 0;
    in >> magic >> w >> h >> scale;
    in.get();  // the single whitespace byte after the header
    if (!in || magic != "PF" || w <= 0 || h <= 0 || w > 65536 || h > 65536 || scale >= 0)
        throw std::runtime_error("cannot read image " + path + ": not a little-endian colour PFM");
    Image image(w, h);
    for (int y = h - 1; y >= 0; --y)
        for (int x = 0; x < w; ++x) {
            float rgb[3];
            if (!in.read(reinterpret_cast<char*>(rgb), sizeof rgb))
                throw std::runtime_error("cannot read image " + path + ": file is truncated");
            image.at(x, y) = Color(rgb[0], rgb[1], rgb[2]);
        }
    return image;
}

}  // namespace rt
