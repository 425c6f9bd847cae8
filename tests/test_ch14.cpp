// Chapter 14: antialiasing (course §9.11.1). The stratified pattern and the tent warp on
// worked values; the tent's distribution against its formula; where camera_sample puts a
// pixel's samples for each pattern and filter; a pixel cut by an edge against the area it
// covers, computed by integration; and jittering beating random sampling at equal samples.
// (The statistical test of tools/ztest.hpp, library code, is tested in test_statistics.cpp.)
#include "io/scene_file.hpp"
#include "render/render.hpp"
#include "support.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

using namespace rt;
using rt::test::kEps;

namespace {

// A few units in the last place of numbers below 1: how far from the exact (s + u) / n a
// stratified point may land. x / n and x * (1.0 / n) differ by one such unit, and a point at
// a stratum's edge may round into the next stratum by that much: both are right.
constexpr Real kUlps = 4 * kEps;

// Sample k of `count` in pixel (4, 9), asked for as the render loop asks: the sampler told
// the pattern's strata, the sample started.
Vec2 film(Sampler& sampler, int k, int count, const Antialiasing& aa) {
    sampler.set_strata(count, pattern_side(count).value_or(0), strata_of(aa));
    sampler.start_sample(k);
    return camera_sample(4, 9, aa.filter, sampler).film;
}

}  // namespace

TEST_CASE("14.1 stratified_point: sample k at offset u in stratum (k mod n, k div n)") {
    // Each point against (sx + u) / n, to a few ulps, for offsets at a stratum's low edge, in
    // its middle and near its high edge, over patterns of several sizes.
    int failures = 0, points = 0;
    for (const int n : {1, 2, 3, 4, 7, 10, 32})
        for (int k = 0; k < n * n; ++k)
            for (const Vec2 u : {Vec2(0, 0), Vec2(0.5, 0.25), Vec2(Real(k % 5) / 5, Real(k % 3) / 3),
                                 Vec2(Real(0.999), Real(0.001))}) {
                const Vec2 point = stratified_point(k, n, u);
                const int sx = k % n, sy = k / n;
                const Vec2 want((Real(sx) + u.x) / Real(n), (Real(sy) + u.y) / Real(n));
                const Vec2 stratum_low(Real(sx) / Real(n), Real(sy) / Real(n));
                const Vec2 stratum_high(Real(sx + 1) / Real(n), Real(sy + 1) / Real(n));
                CAPTURE(k);
                CAPTURE(n);
                CAPTURE(u);
                CAPTURE(point);
                CAPTURE(want);
                CAPTURE(stratum_low);
                CAPTURE(stratum_high);
                RT_CHECK_FIRST(failures, std::abs(point.x - want.x) <= kUlps);
                RT_CHECK_FIRST(failures, std::abs(point.y - want.y) <= kUlps);
                RT_CHECK_FIRST(failures, point.x >= 0);
                RT_CHECK_FIRST(failures, point.y >= 0);
                RT_CHECK_FIRST(failures, point.x < 1);
                RT_CHECK_FIRST(failures, point.y < 1);
                ++points;
            }
    CHECK(failures == 0);
    CHECK(points > 4000);
}

TEST_CASE("14.1 stratified_point: the largest u below 1 stays below 1") {
    // (n - 1 + u) / n rounds up to exactly 1 for u just below 1 (in every form: divided by n
    // or times 1 / n). The contract keeps every point in [0, 1)^2, so something must stop it.
    const Real below_one = 1 - kEps / 2;
    for (const int n : {1, 3, 32}) {
        const Vec2 u(below_one);
        const Vec2 point = stratified_point(n * n - 1, n, u);
        CAPTURE(n);
        CAPTURE(u);
        CAPTURE(point);
        CHECK(point.x < 1);
        CHECK(point.y < 1);
        CHECK(point.x >= 1 - 2 * kUlps);
        CHECK(point.y >= 1 - 2 * kUlps);
    }
}

TEST_CASE("14.2 tent_offset: worked values, monotone, and the tent's distribution") {
    // Worked values, to a few ulps (the square roots are exact here, but another correct form
    // of the inverse may round differently).
    const double worked[][2] = {{0.0, -1.0}, {0.125, -0.5}, {0.5, 0.0}, {0.875, 0.5}};  // u, x
    for (const auto& pair : worked) {
        const double u = pair[0], x = pair[1];
        const Real got = tent_offset(Real(u));
        CAPTURE(u);
        CAPTURE(got);
        CHECK(std::abs(got - Real(x)) <= kUlps);
    }
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
        CAPTURE(share);
        CAPTURE(want);
        CHECK(std::abs(share - want) <= 2.0 / n);
    }
}

TEST_CASE("camera_sample: the pixel centre, the strata, the regular grid, the tent") {
    Sampler sampler(7, 3);
    const Antialiasing box_random{};
    CHECK(film(sampler, 0, 1, box_random) == Vec2(4.5, 9.5));
    CHECK(sampler.draws()[std::size_t(Dimension::pixel)] == 0);  // the centre draws nothing
    // Jittered, 16 samples: one in each quarter-by-quarter stratum of the pixel, sample k in
    // stratum k (the pixel's strata in order), at the place two numbers of the pixel
    // dimension's stream give: a twin sampler drawing them itself finds the same points.
    Sampler twin(7, 3);
    std::set<std::pair<int, int>> strata;
    for (int k = 0; k < 16; ++k) {
        const Vec2 f = film(sampler, k, 16, {PixelPattern::jittered, PixelFilter::box});
        CHECK(f == Vec2(4, 9) + stratified_point(k, 4, twin.get2(Dimension::pixel)));
        CHECK(f.x >= 4);
        CHECK(f.x < 5);
        CHECK(f.y >= 9);
        CHECK(f.y < 10);
        strata.insert({int((f.x - 4) * 4), int((f.y - 9) * 4)});
    }
    CHECK(strata.size() == 16);
    // Random, 16 samples: two numbers each, anywhere in the pixel.
    for (int k = 0; k < 16; ++k) CHECK(film(sampler, k, 16, box_random) == Vec2(4, 9) + twin.get2(Dimension::pixel));
    CHECK(sampler.draws()[std::size_t(Dimension::pixel)] == 64);
    // Regular: the strata's centres, whatever the sampler, and nothing drawn.
    CHECK(film(sampler, 6, 16, {PixelPattern::regular, PixelFilter::box}) == Vec2(4 + 2.5 / 4, 9 + 1.5 / 4));
    CHECK(sampler.draws()[std::size_t(Dimension::pixel)] == 64);
    // Tent: within one pixel of the centre, centred on it, and denser near it.
    double sum_x = 0, near = 0;
    const int n = 4096;
    for (int k = 0; k < n; ++k) {
        const Vec2 f = film(sampler, k, n, {PixelPattern::jittered, PixelFilter::tent});
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
