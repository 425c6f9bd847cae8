// rtlab-diff: compares two images (PNG or PFM) as a grader does.
//
// Errors are in 8-bit levels of the encoded (sRGB) values, per channel, which is what a
// viewer sees. With --radius R, each pixel is compared with the best-matching pixel within
// R of it in the other image, both ways, so an edge that moved by a pixel is not an error.
//
// Exit: 0 within tolerance, 1 past it, 2 bad input.
#include "core/text.hpp"
#include "io/image_file.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <vector>

namespace {

struct Levels {
    int w, h;
    std::vector<float> v;  // w*h*3, 0..255
    float at(int x, int y, int c) const {
        return v[(std::size_t(y) * std::size_t(w) + std::size_t(x)) * 3 + std::size_t(c)];
    }
};

Levels levels(const rt::Image& img) {
    Levels l{img.width, img.height, std::vector<float>(img.pixels.size() * 3)};
    for (std::size_t i = 0; i < img.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            l.v[3 * i + std::size_t(c)] = std::round(255.0f * rt::linear_to_srgb(img.pixels[i][c]));
    return l;
}

// Per pixel: the largest channel error against the best match within `radius` in `b`.
std::vector<float> one_way(const Levels& a, const Levels& b, int radius, std::vector<float>& sq) {
    std::vector<float> err(std::size_t(a.w) * std::size_t(a.h));
    sq.assign(err.size(), 0);
    for (int y = 0; y < a.h; ++y)
        for (int x = 0; x < a.w; ++x) {
            float best = std::numeric_limits<float>::infinity(), best_sq = 0;
            for (int dy = -radius; dy <= radius; ++dy)
                for (int dx = -radius; dx <= radius; ++dx) {
                    const int bx = x + dx, by = y + dy;
                    if (bx < 0 || by < 0 || bx >= b.w || by >= b.h) continue;
                    float m = 0, s = 0;
                    for (int c = 0; c < 3; ++c) {
                        const float d = std::abs(a.at(x, y, c) - b.at(bx, by, c));
                        m = std::max(m, d);
                        s += d * d;
                    }
                    if (m < best) best = m, best_sq = s;
                }
            err[std::size_t(y) * std::size_t(a.w) + std::size_t(x)] = best;
            sq[std::size_t(y) * std::size_t(a.w) + std::size_t(x)] = best_sq;
        }
    return err;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App cli{"rtlab-diff: compare two images (PNG or PFM)", "rtlab-diff"};
    std::string a_path, b_path, heatmap;
    int radius = 0;
    float threshold = 8, max_rmse = -1, max_over = -1, min_psnr = -1, max_error = -1;
    cli.add_option("A", a_path, "first image (e.g. the reference)")->required();
    cli.add_option("B", b_path, "second image (e.g. the render)")->required();
    // A tolerance is a finite number in range: CLI::Range alone lets "nan" through.
    const auto within = [](double lo, double hi) {
        return CLI::Validator(
            [lo, hi](std::string& value) {
                char* end = nullptr;
                const double v = std::strtod(value.c_str(), &end);
                return end != value.c_str() && *end == '\0' && v >= lo && v <= hi
                           ? std::string()
                           : "must be a number in " + std::to_string(int(lo)) + ".." + std::to_string(int(hi)) +
                                 ", not '" + value + "'";
            },
            "");
    };
    cli.add_option("--heatmap", heatmap, "write a PNG of the per-pixel error here");
    cli.add_option("--radius", radius, "neighbourhood radius in pixels for edge tolerance")->check(CLI::Range(0, 8));
    cli.add_option("--threshold", threshold, "a pixel is 'over' if its error exceeds this many levels")
        ->check(within(0, 255));
    cli.add_option("--max-rmse", max_rmse, "fail if RMSE (levels) exceeds this")->check(within(0, 255));
    cli.add_option("--max-over", max_over, "fail if more than this percentage of pixels is over the threshold")
        ->check(within(0, 100));
    cli.add_option("--min-psnr", min_psnr, "fail if PSNR (dB) is below this")->check(within(0, 1000));
    cli.add_option("--max-error", max_error, "fail if any pixel's error (levels) exceeds this")->check(within(0, 255));
    try {
        cli.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return cli.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "rtlab-diff: error: %s\n", rt::one_line(e.what()).c_str());
        return 2;
    }
    if (!heatmap.empty() && std::filesystem::path(heatmap).extension() != ".png") {
        std::fprintf(stderr, "rtlab-diff: error: --heatmap: '%s' must end in .png\n", heatmap.c_str());
        return 2;
    }

    Levels a, b;
    try {
        a = levels(rt::read_image(a_path));
        b = levels(rt::read_image(b_path));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "rtlab-diff: error: %s\n", rt::one_line(e.what()).c_str());
        return 2;
    }
    if (a.w != b.w || a.h != b.h) {
        std::fprintf(stderr, "rtlab-diff: error: sizes differ: %s is %dx%d, %s is %dx%d\n", a_path.c_str(), a.w, a.h,
                     b_path.c_str(), b.w, b.h);
        return 2;
    }

    std::vector<float> sq_ab, sq_ba;
    const auto ab = one_way(a, b, radius, sq_ab);
    const auto ba = one_way(b, a, radius, sq_ba);
    const std::size_t n = ab.size();
    double sum_sq = 0, sum_abs = 0, worst = 0;
    std::size_t over = 0;
    std::vector<float> err(n);
    for (std::size_t i = 0; i < n; ++i) {
        err[i] = std::max(ab[i], ba[i]);
        sum_sq += std::max(sq_ab[i], sq_ba[i]) / 3.0;
        sum_abs += err[i];
        worst = std::max(worst, double(err[i]));
        if (err[i] > threshold) ++over;
    }
    const double rmse = std::sqrt(sum_sq / double(n));
    const double psnr = rmse > 0 ? 20.0 * std::log10(255.0 / rmse) : std::numeric_limits<double>::infinity();
    const double over_pct = 100.0 * double(over) / double(n);
    std::printf("rmse %.4f  psnr %.2f dB  max %.0f  mean %.4f  over %.4f%% (threshold %.0f, radius %d)\n", rmse, psnr,
                worst, sum_abs / double(n), over_pct, threshold, radius);

    if (!heatmap.empty()) {
        // Black where equal, through red to yellow at 64 levels and more.
        rt::Image map(a.w, a.h);
        for (std::size_t i = 0; i < n; ++i) {
            const float e = std::min(err[i] / 64.0f, 1.0f);
            map.pixels[i] = rt::Color(std::min(2 * e, 1.0f), std::max(2 * e - 1, 0.0f), 0.0f);
        }
        try {
            rt::write_png(map, heatmap);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "rtlab-diff: error: %s\n", rt::one_line(e.what()).c_str());
            return 2;
        }
    }

    bool pass = true;
    auto fail = [&](const char* what, double value, double limit) {
        std::printf("FAIL: %s %.4f past the tolerance %.4f\n", what, value, limit);
        pass = false;
    };
    if (max_rmse >= 0 && rmse > max_rmse) fail("rmse", rmse, max_rmse);
    if (max_over >= 0 && over_pct > max_over) fail("over%", over_pct, max_over);
    if (min_psnr >= 0 && psnr < min_psnr) fail("psnr", psnr, min_psnr);
    if (max_error >= 0 && worst > max_error) fail("max", worst, max_error);
    return pass ? 0 : 1;
}
