// Chapter 14: antialiasing (course §9.11.1). The stratified pattern and the tent warp on
// worked values; the tent's distribution against its formula; where camera_sample puts a
// pixel's samples for each pattern and filter; a pixel cut by an edge against the area it
// covers, computed by integration; and jittering beating random sampling at equal samples.
// (The statistical test of tools/ztest.hpp, library code, is tested in test_library_parts.cpp.)
#include "io/scene_file.hpp"
#include "render/render.hpp"
#include "support.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

using namespace rt;
using rt::test::kEps;

TEST_CASE("14.1 stratified_point: one sample in each of the n x n strata") {
    CHECK(stratified_point(0, 1, Vec2(0.25, 0.75)) == Vec2(0.25, 0.75));
    const Vec2 p = stratified_point(5, 4, Vec2(0.5, 0.5));  // stratum (1, 1) of 4 x 4
    CHECK(p.x == Real(0.375));
    CHECK(p.y == Real(0.375));
    const Vec2 q = stratified_point(11, 4, Vec2(0, 0.5));  // stratum (3, 2)
    CHECK(q.x == Real(0.75));
    CHECK(q.y == Real(0.625));
    for (int n : {1, 2, 3, 7, 32}) {
        std::set<std::pair<int, int>> seen;
        for (int k = 0; k < n * n; ++k) {
            const Vec2 u(Real(k % 5) / 5, Real(k % 3) / 3);
            const Vec2 s = stratified_point(k, n, u);
            CHECK(s.x >= 0);
            CHECK(s.x < 1);
            CHECK(s.y >= 0);
            CHECK(s.y < 1);
            seen.insert({int(std::floor(s.x * Real(n))), int(std::floor(s.y * Real(n)))});
        }
        CHECK(seen.size() == std::size_t(n * n));
    }
    // The largest u below 1 stays inside its stratum, hence below 1.
    const Real below_one = 1 - kEps / 2;
    CHECK(stratified_point(1023, 32, Vec2(below_one)).x < 1);
}

TEST_CASE("14.2 tent_offset: worked values, monotone, and the tent's distribution") {
    CHECK(tent_offset(0) == -1);
    CHECK(tent_offset(Real(0.125)) == Real(-0.5));
    CHECK(tent_offset(Real(0.5)) == 0);
    CHECK(tent_offset(Real(0.875)) == Real(0.5));
    CHECK(tent_offset(1 - kEps / 2) < 1);
    // Its distribution function is (1 + x)^2 / 2 left of 0 and 1 - (1 - x)^2 / 2 right of it:
    // the share of 100,000 evenly spread u below each x is that, to the spacing.
    const int n = 100000;
    std::vector<Real> xs(n);
    for (int k = 0; k < n; ++k) xs[std::size_t(k)] = tent_offset((Real(k) + Real(0.5)) / Real(n));
    CHECK(std::is_sorted(xs.begin(), xs.end()));
    for (double x : {-0.9, -0.5, -0.1, 0.0, 0.3, 0.75, 0.99}) {
        const double share = double(std::lower_bound(xs.begin(), xs.end(), Real(x)) - xs.begin()) / double(n);
        const double want = x < 0 ? (1 + x) * (1 + x) / 2 : 1 - (1 - x) * (1 - x) / 2;
        CAPTURE(x);
        CHECK(std::abs(share - want) <= 2.0 / n);
    }
}

TEST_CASE("camera_sample: the pixel centre, the strata, the regular grid, the tent") {
    Sampler sampler(7, 3);
    const Antialiasing box_random{};
    CHECK(camera_sample(4, 9, 0, 1, box_random, sampler).film == Vec2(4.5, 9.5));
    // Jittered, 16 samples: one in each quarter-by-quarter stratum of the pixel.
    std::set<std::pair<int, int>> strata;
    for (int k = 0; k < 16; ++k) {
        const Vec2 f = camera_sample(4, 9, k, 16, {PixelPattern::jittered, PixelFilter::box}, sampler).film;
        CHECK(f.x >= 4);
        CHECK(f.x < 5);
        CHECK(f.y >= 9);
        CHECK(f.y < 10);
        strata.insert({int((f.x - 4) * 4), int((f.y - 9) * 4)});
    }
    CHECK(strata.size() == 16);
    // Regular: the strata's centres, whatever the sampler.
    CHECK(camera_sample(4, 9, 6, 16, {PixelPattern::regular, PixelFilter::box}, sampler).film ==
          Vec2(4 + 2.5 / 4, 9 + 1.5 / 4));
    // Tent: within one pixel of the centre, centred on it, and denser near it.
    double sum_x = 0, near = 0;
    const int n = 4096;
    for (int k = 0; k < n; ++k) {
        const Vec2 f = camera_sample(4, 9, k, n, {PixelPattern::jittered, PixelFilter::tent}, sampler).film;
        CHECK(std::abs(f.x - Real(4.5)) < 1);
        CHECK(std::abs(f.y - Real(9.5)) < 1);
        sum_x += double(f.x) - 4.5;
        near += std::abs(f.x - Real(4.5)) < Real(0.5);
    }
    CHECK(std::abs(sum_x / n) < 1e-3);
    CHECK(std::abs(near / n - 0.75) < 1e-3);  // the tent's mass within half a pixel: 3/4
}

namespace {

// Eight by eight pixels, each one unit of the world, looking straight at a white half-plane
// y < 0.3 x + 0.1 on black: a pixel's value is the share of it the half-plane covers.
Scene edge_scene() {
    const std::string text = R"({"camera": {"projection": "orthographic", "eye": [0, 0, 1], "target": [0, 0, 0],
  "window_height": 8}, "ambient": [1, 1, 1], "background": [0, 0, 0],
  "materials": {"white": {"diffuse": [1, 1, 1]}},
  "surfaces": [{"type": "polygon", "vertices": [[-50, -50, 0], [50, -50, 0], [50, 15.1, 0], [-50, -14.9, 0]],
                "material": "white"}]})";
    Scene scene = load_scene_text(text, "edge.json", ".");
    scene.build_accel(AccelKind::none);
    return scene;
}

// The share of the unit square at (x0, y0) below the line, by the midpoint rule in x.
double coverage(double x0, double y0) {
    const int n = 100000;
    double area = 0;
    for (int k = 0; k < n; ++k) {
        const double x = x0 + (k + 0.5) / n;
        area += std::clamp(0.3 * x + 0.1 - y0, 0.0, 1.0) / n;
    }
    return area;
}

// Mean absolute error of the image against the covered areas, over the pixels the edge crosses.
double edge_error(const Image& img) {
    double sum = 0;
    int count = 0;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const double want = coverage(x - 4.0, 3.0 - y);  // image rows go down
            if (want <= 0 || want >= 1) continue;
            sum += std::abs(double(img.at(x, y).r) - want);
            ++count;
        }
    CHECK(count >= 8);
    return sum / count;
}

// The edge scene's 8 x 8 image, one thread, `spp` samples with the box filter.
RenderOptions edge_options(int spp, PixelPattern pattern) {
    RenderOptions o;
    o.width = o.height = 8;
    o.threads = 1;
    o.spp = spp;
    o.antialiasing = {pattern, PixelFilter::box};
    return o;
}

}  // namespace

TEST_CASE("a pixel cut by an edge: its value is the area covered (box filter), to the sampling error") {
    const Scene scene = edge_scene();
    RenderOptions o = edge_options(1024, PixelPattern::jittered);
    const Image img = render(scene, o).image;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            CAPTURE(x);
            CAPTURE(y);
            // 32 x 32 strata: only the strata the edge crosses (about 32 of 1024) are uncertain.
            CHECK(std::abs(double(img.at(x, y).r) - coverage(x - 4.0, 3.0 - y)) < 0.02);
        }
    // The regular grid's answer is a count of grid points: off by up to the edge's strata.
    o.antialiasing.pattern = PixelPattern::regular;
    CHECK(edge_error(render(scene, o).image) < 0.02);
}

TEST_CASE("at 16 samples, jittering errs less than random sampling on the edge pixels") {
    const Scene scene = edge_scene();
    RenderOptions o = edge_options(16, PixelPattern::random);
    double random_error = 0, jittered_error = 0;
    for (std::uint64_t seed = 1; seed <= 16; ++seed) {
        o.seed = seed;
        o.antialiasing.pattern = PixelPattern::random;
        random_error += edge_error(render(scene, o).image);
        o.antialiasing.pattern = PixelPattern::jittered;
        jittered_error += edge_error(render(scene, o).image);
    }
    CAPTURE(random_error / 16);
    CAPTURE(jittered_error / 16);
    // Random: about sqrt(c (1 - c) / 16), ~0.09; jittered: only the ~4 strata on the edge vary.
    CHECK(jittered_error < 0.6 * random_error);
}
