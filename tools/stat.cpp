// rtlab-stat: the statistical image test of the noisy chapters (book §14.6; tools/ztest.hpp).
//
//   rtlab-stat reference MEAN.pfm VAR.pfm --converged A.pfm... --spread B.pfm...
//       a reference: MEAN, the average of the converged renders (many samples per pixel);
//       VAR, the variance of one render about its mean, over the spread renders (made at the
//       test's settings, with as many seeds as can be afforded).
//   rtlab-stat test MEAN.pfm VAR.pfm IMAGE.pfm... [--alpha A] [--floor F] [--var-renders N]
//       [--map F.png] [--json F.json]   M >= 2 renders against a reference: a t-test per
//       pixel-channel (the variance was estimated from N renders); fail when any p-value is
//       below the level that Šidák's correction gives alpha over all of them.
//
// Exit: 0 pass (or reference written), 1 the test failed, 2 bad input.
#include "core/text.hpp"
#include "io/image_file.hpp"
#include "ztest.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace {

std::vector<double> values(const rt::Image& img) {
    std::vector<double> v;
    v.reserve(img.pixels.size() * 3);
    for (const rt::Color& c : img.pixels)
        for (int k = 0; k < 3; ++k) v.push_back(double(c[k]));
    return v;
}

rt::Image image_of(const std::vector<double>& v, int w, int h) {
    rt::Image img(w, h);
    for (std::size_t i = 0; i < img.pixels.size(); ++i)
        img.pixels[i] = rt::Color(float(v[3 * i]), float(v[3 * i + 1]), float(v[3 * i + 2]));
    return img;
}

// Black where every channel agrees easily; orange, brighter as p falls towards the
// corrected level; red where a channel fails.
rt::Image failure_map(const rt::stat::Verdict& v, int w, int h) {
    rt::Image img(w, h);
    const double scale = -std::log10(v.level);
    for (std::size_t i = 0; i < img.pixels.size(); ++i) {
        const double p = std::min({v.p[3 * i], v.p[3 * i + 1], v.p[3 * i + 2]});
        if (p < v.level)
            img.pixels[i] = rt::Color(1, 0, 0);
        else if (p < 0.01)
            img.pixels[i] = rt::Color(1, 0.5f, 0) * float(std::min(1.0, -std::log10(p) / scale));
    }
    return img;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App cli{"rtlab-stat: statistical image test (a t-test per pixel-channel, Sidak-corrected)", "rtlab-stat"};
    cli.require_subcommand(1);
    std::string mean_path, var_path, map_path, json_path, average_path, reference_png;
    std::vector<std::string> images, converged, spread;
    // The defaults are the tests' tolerance (RTLAB_STAT_TOLERANCE in tools/settings.cmake, book
    // §14.6), so a test run by hand gives the verdict the test suite gives (stat_defaults checks).
    double alpha = 0.01, floor = 0.004, max_share = 0;
    std::size_t var_renders = 1024;
    CLI::App* make = cli.add_subcommand("reference", "write a reference: the converged mean, one render's variance");
    CLI::App* test = cli.add_subcommand("test", "test M renders against a reference");
    for (CLI::App* sub : {make, test}) {
        sub->add_option("MEAN", mean_path, "mean image (.pfm)")->required();
        sub->add_option("VAR", var_path, "one render's variance (.pfm)")->required();
    }
    make->add_option("--converged", converged, "renders with many samples per pixel (.pfm)")
        ->required()
        ->expected(1, 1 << 16);
    make->add_option("--spread", spread, ">= 2 renders at the test's settings (.pfm)")
        ->required()
        ->expected(2, 1 << 16);
    test->add_option("IMAGES", images, "M >= 2 renders (.pfm), one per seed")->required()->expected(2, 1 << 16);
    test->add_option("--alpha", alpha, "false-alarm rate of the whole image")->check(CLI::Range(1e-9, 0.5));
    test->add_option("--floor", floor, "standard deviation added to every test (rounding, storage)")
        ->check(CLI::Range(0.0, 1.0));
    test->add_option("--var-renders", var_renders,
                     "renders the reference's variance was estimated from (0: take it as exact, a z-test)")
        ->check(CLI::Range(std::size_t(0), std::size_t(1) << 30));
    // The tests' tolerance comes first on a command line; a value given after it wins.
    for (const char* name : {"--alpha", "--floor", "--var-renders"})
        test->get_option(name)->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    // Hidden: an old command line gets a reason, not "not expected".
    CLI::Option* gone = test->add_option("--max-share", max_share)->group("");
    test->add_option("--map", map_path, "write a PNG map of the failing pixels");
    test->add_option("--json", json_path, "write the verdict as JSON");
    test->add_option("--average", average_path, "write the average of the renders (.png or .pfm)");
    test->add_option("--reference-image", reference_png, "write the reference's mean as an image (.png or .pfm)");
    try {
        cli.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return cli.exit(e);
        std::fprintf(stderr, "rtlab-stat: error: %s\n", rt::one_line(e.what()).c_str());
        return 2;
    }
    if (var_renders == 1) {
        std::fprintf(stderr, "rtlab-stat: error: --var-renders 1: one render has no variance\n");
        return 2;
    }
    if (gone->count() > 0) {
        std::fprintf(stderr,
                     "rtlab-stat: error: --max-share is gone: no pixel-channel may fail at the corrected "
                     "level, whose false-alarm rate --alpha states (book §14.6)\n");
        return 2;
    }
    try {
        int w = 0, h = 0;
        const auto read_all = [&](const std::vector<std::string>& paths) {
            std::vector<std::vector<double>> all;
            for (const std::string& path : paths) {
                const rt::Image img = rt::read_image(path);
                if (w == 0) w = img.width, h = img.height;
                if (img.width != w || img.height != h)
                    throw std::runtime_error(path + " is " + std::to_string(img.width) + "x" +
                                             std::to_string(img.height) + ", not " + std::to_string(w) + "x" +
                                             std::to_string(h));
                all.push_back(values(img));
            }
            return all;
        };
        if (make->parsed()) {
            const auto high = read_all(converged);
            const auto low = read_all(spread);
            std::vector<double> mean(high.front().size(), 0);
            for (const auto& r : high)
                for (std::size_t i = 0; i < mean.size(); ++i) mean[i] += r[i] / double(high.size());
            rt::write_image(image_of(mean, w, h), mean_path);
            rt::write_image(image_of(rt::stat::mean_var(low).var, w, h), var_path);
            std::printf("reference: mean of %zu converged renders in %s, variance of %zu renders in %s\n", high.size(),
                        mean_path.c_str(), low.size(), var_path.c_str());
            return 0;
        }
        const auto renders = read_all(images);
        const rt::Image ref_mean = rt::read_image(mean_path), ref_var = rt::read_image(var_path);
        if (ref_mean.width != w || ref_mean.height != h || ref_var.width != w || ref_var.height != h)
            throw std::runtime_error("the reference is " + std::to_string(ref_mean.width) + "x" +
                                     std::to_string(ref_mean.height) + ", the renders " + std::to_string(w) + "x" +
                                     std::to_string(h));
        const rt::stat::MeanVar ref{values(ref_mean), values(ref_var)};
        const rt::stat::Verdict v = rt::stat::compare(renders, ref, alpha, floor, var_renders);
        char test_name[64] = "z-test";
        if (var_renders > 1) std::snprintf(test_name, sizeof test_name, "t-test (variance of %zu)", var_renders);
        char line[512];
        std::snprintf(line, sizeof line,
                      "%s: %zu renders, %zu pixel-channels, %zu fail at p < %.3g (alpha %.3g, Sidak): %s; "
                      "smallest p %.3g",
                      test_name, renders.size(), v.tests, v.failed, v.level, alpha, v.pass() ? "pass" : "FAIL",
                      v.smallest_p);
        std::printf("%s\n", line);
        if (!map_path.empty()) rt::write_image(failure_map(v, w, h), map_path);
        if (!average_path.empty()) {
            std::vector<double> average(v.tests, 0);
            for (const auto& r : renders)
                for (std::size_t i = 0; i < v.tests; ++i) average[i] += r[i] / double(renders.size());
            rt::write_image(image_of(average, w, h), average_path);
        }
        if (!reference_png.empty()) rt::write_image(ref_mean, reference_png);
        if (!json_path.empty()) {
            char json[512];
            std::snprintf(json, sizeof json,
                          "{\"renders\": %zu, \"tests\": %zu, \"failed\": %zu, \"level\": %.6g, "
                          "\"alpha\": %.6g, \"var_renders\": %zu, \"smallest_p\": %.6g, \"pass\": %s}\n",
                          renders.size(), v.tests, v.failed, v.level, alpha, var_renders, v.smallest_p,
                          v.pass() ? "true" : "false");
            rt::write_file_atomically(json_path, json);
        }
        return v.pass() ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "rtlab-stat: error: %s\n", rt::one_line(e.what()).c_str());
        return 2;
    }
}
