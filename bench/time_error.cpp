// Time against error (book §14.5; issue "fast and accurate"): each scene rendered at rising
// samples per pixel with each pattern of pixel samples, and the error of each image against a
// converged reference, so that a sampler is judged by the error it reaches in a given time.
//
//   build/release/bin/bench_time_error [--width W] [--height H] [--seeds S] [--csv FILE] SCENE.json...
//
// The reference: 4096 jittered samples per pixel (64 x 64 strata). Each (pattern, spp) is
// rendered with S seeds (default 4); its RMSE (linear RGB, over all pixel-channels) is the
// root of the mean squared error over the seeds, its time the mean wall time of one render.
// Prints a table, the log-log slopes of RMSE against samples and against time, and how much
// less time jittering needs than random sampling for the RMSE random sampling reaches at its
// largest sample count. Writes CSV rows: scene,pattern,spp,seconds,rays,rmse,relative_error.
// ./lab bench time-error runs it on the noisy chapters' scenes and plots the CSV
// (bench/time_error.gnuplot).
#include "fit.hpp"
#include "io/scene_file.hpp"
#include "render/render.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace rt;

namespace {

struct Row {
    std::string scene;
    PixelPattern pattern;
    int spp;
    double seconds, rays, rmse, relative;
};

double mean_value(const Image& img) {
    double sum = 0;
    for (const Color& c : img.pixels) sum += double(c.r) + double(c.g) + double(c.b);
    return sum / (3.0 * double(img.pixels.size()));
}

double squared_error(const Image& a, const Image& b) {
    double sum = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double d = double(a.pixels[i][c]) - double(b.pixels[i][c]);
            sum += d * d;
        }
    return sum / (3.0 * double(a.pixels.size()));
}

}  // namespace

int main(int argc, char** argv) {
    RenderOptions base;
    base.width = 96;
    base.height = 72;
    int seeds = 4;
    std::string csv_path;
    std::vector<std::string> scenes;
    for (int i = 1; i < argc; ++i) {
        const auto value = [&](const char* name) {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "bench_time_error: %s needs a value\n", name);
                std::exit(2);
            }
            return std::string(argv[++i]);
        };
        if (!std::strcmp(argv[i], "--width"))
            base.width = std::atoi(value("--width").c_str());
        else if (!std::strcmp(argv[i], "--height"))
            base.height = std::atoi(value("--height").c_str());
        else if (!std::strcmp(argv[i], "--seeds"))
            seeds = std::atoi(value("--seeds").c_str());
        else if (!std::strcmp(argv[i], "--csv"))
            csv_path = value("--csv");
        else
            scenes.push_back(argv[i]);
    }
    if (scenes.empty() || seeds < 1 || base.width < 1 || base.height < 1) {
        std::fprintf(stderr,
                     "usage: bench_time_error [--width W] [--height H] [--seeds S] [--csv FILE] SCENE.json...\n");
        return 2;
    }

    std::vector<Row> rows;
    try {
        for (const std::string& path : scenes) {
            Scene scene = load_scene_file(path);
            scene.build_accel(scene.accel_kind);
            const std::string name = std::filesystem::path(path).stem().string();
            RenderOptions ref = base;
            ref.antialiasing = {PixelPattern::jittered, scene.antialiasing.filter};
            ref.spp = 4096;
            ref.seed = 999;
            const Image reference = render(scene, ref).image;
            const double mean = mean_value(reference);
            std::printf("%s (%dx%d, %s filter; reference 4096 jittered samples per pixel, mean %.4f)\n", name.c_str(),
                        base.width, base.height, kFilterNames[scene.antialiasing.filter], mean);
            std::printf("  %-9s %6s %10s %12s %10s %9s\n", "pattern", "spp", "seconds", "rays", "RMSE", "relative");
            for (PixelPattern pattern : {PixelPattern::random, PixelPattern::jittered})
                for (int spp : {4, 16, 64, 256, 1024}) {
                    RenderOptions o = base;
                    o.antialiasing = {pattern, scene.antialiasing.filter};
                    o.spp = spp;
                    double seconds = 0, rays = 0, squared = 0;
                    for (int s = 0; s < seeds; ++s) {
                        o.seed = std::uint64_t(1 + s);
                        const auto start = std::chrono::steady_clock::now();
                        const RenderResult r = render(scene, o);
                        seconds +=
                            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / seeds;
                        rays += double(r.counters.total()) / seeds;
                        squared += squared_error(r.image, reference) / seeds;
                    }
                    const Row row{name, pattern, spp, seconds, rays, std::sqrt(squared), std::sqrt(squared) / mean};
                    std::printf("  %-9s %6d %10.4f %12.0f %10.6f %9.5f\n", kPatternNames[pattern], spp, row.seconds,
                                row.rays, row.rmse, row.relative);
                    std::fflush(stdout);
                    rows.push_back(row);
                }
            // Slopes, and the time each pattern needs for random sampling's error at 1024 spp.
            std::vector<double> spp[2], time[2], err[2];
            for (const Row& r : rows)
                if (r.scene == name) {
                    const int k = r.pattern == PixelPattern::jittered;
                    spp[k].push_back(r.spp);
                    time[k].push_back(r.seconds);
                    err[k].push_back(r.rmse);
                }
            for (int k = 0; k < 2; ++k)
                std::printf("  %-9s RMSE ~ spp^%.2f, ~ time^%.2f\n", k ? "jittered" : "random",
                            bench::loglog_slope(spp[k], err[k]), bench::loglog_slope(time[k], err[k]));
            const double target = err[0].back();
            const double t_jittered = bench::loglog_reach(time[1], err[1], target);
            std::printf("  at random's RMSE at 1024 spp (%.6f): random %.4f s, jittered %.4f s: %.1fx less time\n\n",
                        target, time[0].back(), t_jittered, time[0].back() / t_jittered);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_time_error: %s\n", e.what());
        return 2;
    }

    if (!csv_path.empty()) {
        std::ofstream csv(csv_path);
        csv << "scene,pattern,spp,seconds,rays,rmse,relative_error\n";
        for (const Row& r : rows)
            csv << r.scene << ',' << kPatternNames[r.pattern] << ',' << r.spp << ',' << r.seconds << ',' << r.rays
                << ',' << r.rmse << ',' << r.relative << '\n';
        if (!csv) {
            std::fprintf(stderr, "bench_time_error: cannot write %s\n", csv_path.c_str());
            return 1;
        }
    }
    return 0;
}
