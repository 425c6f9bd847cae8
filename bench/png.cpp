// Writing a PNG: the lab's encoder (libspng, zlib's fastest level, no row filter, sRGB codes
// from a table) against the one it replaced (pow per channel, then stb_image_write), side by
// side on one image, best of RUNS each. Both must give the same pixels.
//
//   bench_png IMAGE.pfm [RUNS]     e.g. after
//   ch10 --scene bench/scenes/spheres488.json --width 1280 --height 720 -o spheres.pfm
#include "io/image_file.hpp"

#include <stb_image_write.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace {

using namespace rt;

std::string stb_png(const Image& image) {
    std::vector<unsigned char> bytes(image.pixels.size() * 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            bytes[3 * i + std::size_t(c)] =
                static_cast<unsigned char>(std::lround(255.0f * linear_to_srgb(image.pixels[i][c])));
    std::string out;
    stbi_write_png_to_func(
        [](void* context, void* data, int size) {
            static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
        },
        &out, image.width, image.height, 3, bytes.data(), image.width * 3);
    return out;
}

template <class Encode>
double best_seconds(int runs, std::string& bytes, Encode encode) {
    double best = 1e30;
    for (int r = 0; r < runs; ++r) {
        const auto start = std::chrono::steady_clock::now();
        bytes = encode();
        best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    return best;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: bench_png IMAGE.pfm [RUNS]\n");
        return 2;
    }
    try {
        const Image image = read_pfm(argv[1]);
        const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 10;
        std::string lab, stb;
        const double t_lab = best_seconds(runs, lab, [&] { return encode_png(image); });
        const double t_stb = best_seconds(runs, stb, [&] { return stb_png(image); });
        const Image a = decode_png(lab, "lab"), b = decode_png(stb, "stb");
        const bool same = a.pixels == b.pixels;
        std::printf("| encoder | seconds | bytes |\n|---|---|---|\n");
        std::printf("| libspng, level 1, no filter | %.4f | %zu |\n", t_lab, lab.size());
        std::printf("| stb_image_write (before) | %.4f | %zu |\n", t_stb, stb.size());
        std::printf("\n%dx%d, best of %d; stb / libspng time %.2f; same pixels: %s\n", image.width, image.height, runs,
                    t_stb / t_lab, same ? "yes" : "NO");
        return same ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_png: %s\n", e.what());
        return 2;
    }
}
