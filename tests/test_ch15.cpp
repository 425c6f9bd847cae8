// Chapter 15: soft shadows (course §9.11.2). The Fisher-Yates shuffle (every order, equally
// often), points of a parallelogram light on worked values, the strata of the light's
// dimension shuffled against the pixel's, and the share of a light seen past an edge
// against its analytic value; a point light draws no light sample.
#include "io/scene_file.hpp"
#include "render/render.hpp"
#include "render/strata.hpp"
#include "support.hpp"
#include "support/small_render.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <vector>

using namespace rt;

TEST_CASE("15.1 fisher_yates: a permutation, and every order equally often") {
    pcg32 random(11);
    for (std::size_t n : {0, 1, 2, 17, 256}) {
        std::vector<std::uint32_t> order(n);
        std::iota(order.begin(), order.end(), 0u);
        fisher_yates(order, random);
        std::vector<std::uint32_t> sorted = order;
        std::sort(sorted.begin(), sorted.end());
        CAPTURE(n);
        int failures = 0;
        for (std::size_t k = 0; k < n; ++k) RT_CHECK_FIRST(failures, sorted[k] == k);  // each item once
        CHECK(failures == 0);
    }
    // The 6 orders of 3 items over 60,000 shuffles: each 10,000 +- 91 (one standard
    // deviation); 500 is 5.5 of them. A shuffle that swaps with any item (not only 0..i)
    // makes some orders twice as likely as others, and fails.
    std::map<std::vector<std::uint32_t>, int> seen;
    for (int k = 0; k < 60000; ++k) {
        std::vector<std::uint32_t> order{0, 1, 2};
        fisher_yates(order, random);
        ++seen[order];
    }
    CHECK(seen.size() == 6);
    for (const auto& entry : seen) {
        const int count = entry.second;  // a named copy: clang 14 cannot capture a structured binding
        const std::string order = std::to_string(entry.first[0]) + std::to_string(entry.first[1]) +
                                  std::to_string(entry.first[2]);  // "120": item 1 first, then 2, then 0
        CAPTURE(order);
        CHECK(std::abs(count - 10000) < 500);
    }
    // Where the first item of 16 ends up: uniform over the 16 places.
    std::vector<int> place(16);
    for (int k = 0; k < 32000; ++k) {
        std::vector<std::uint32_t> order(16);
        std::iota(order.begin(), order.end(), 0u);
        fisher_yates(order, random);
        ++place[std::size_t(std::find(order.begin(), order.end(), 0u) - order.begin())];
    }
    for (std::size_t where = 0; where < place.size(); ++where) {
        const int count = place[where];
        CAPTURE(where);
        CHECK(std::abs(count - 2000) < 250);  // sigma 43
    }
}

TEST_CASE("15.2 light_point: the corner plus u along one edge and v along the other") {
    // Which edge u runs along is the student's choice (the light is the same parallelogram,
    // and the strata shuffled against the pixel's make either way as good): the test finds
    // it from (1, 0) and checks every point against that choice.
    Light light;
    light.type = Light::Type::parallelogram;
    light.position = Vec3(1, 2, 3);
    light.edge_a = Vec3(2, 0, 0);
    light.edge_b = Vec3(0, 1, 4);
    CHECK(light_point(light, Vec2(0, 0)) == Vec3(1, 2, 3));
    const Vec3 along_u = light_point(light, Vec2(1, 0)) - light.position;
    const Real tolerance = 8 * rt::test::kEps * 8;  // a few ulps of coordinates up to 8
    const bool u_along_a = glm::length(along_u - light.edge_a) <= tolerance;
    const bool u_along_b = glm::length(along_u - light.edge_b) <= tolerance;
    CAPTURE(along_u);
    REQUIRE((u_along_a || u_along_b));
    const Vec3 edge_u = u_along_a ? light.edge_a : light.edge_b, edge_v = u_along_a ? light.edge_b : light.edge_a;
    for (const Vec2 uv : {Vec2(0, 1), Vec2(0.5, 0.25), Vec2(0.75, 0.5), Vec2(0.125, 0.875)}) {
        const Vec3 point = light_point(light, uv);
        const Vec3 want = light.position + uv.x * edge_u + uv.y * edge_v;
        CAPTURE(uv);
        CAPTURE(point);
        CAPTURE(want);
        CHECK(glm::length(point - want) <= tolerance);
    }
    // At the centre: where chapter 05's shading (no shadows) puts the whole light.
    const LightSample centre = light.sample(Vec3(2, 0, 5));
    CHECK(centre.distance == doctest::Approx(2.5));
}

TEST_CASE("the light's strata are all used, in an order shuffled against the pixel's") {
    int same_as_pixel = 0;
    for (std::uint64_t pixel = 0; pixel < 200; ++pixel) {
        Sampler s(5, pixel);
        s.set_strata(16, 4, Strata::jittered);
        std::set<std::pair<int, int>> strata;
        bool in_step = true;
        for (int k = 0; k < 16; ++k) {
            s.start_sample(k);
            in_step &= s.stratum(Dimension::light) == k;
            const Vec2 u = sample_square(s, Dimension::light);
            CHECK(u.x >= 0);
            CHECK(u.x < 1);
            CHECK(u.y >= 0);
            CHECK(u.y < 1);
            strata.insert({int(u.x * 4), int(u.y * 4)});
        }
        CHECK(strata.size() == 16);  // one sample in each of the light's 4 x 4 strata
        same_as_pixel += in_step;
    }
    CHECK(same_as_pixel == 0);  // the identity order, 1 in 16! per pixel
    // Each dimension has an order of its own.
    Sampler s(5, 9);
    s.set_strata(16, 4, Strata::jittered);
    int equal = 0;
    for (int k = 0; k < 16; ++k) {
        s.start_sample(k);
        equal += s.stratum(Dimension::light) == s.stratum(Dimension::lens);
    }
    CHECK(equal < 16);
}

namespace {

// A square light 1 wide at height 4 over x, z in [-0.5, 0.5], and a wall at height 2 over
// every x < 0: from the floor point (x, 0, 0), the light's point (l, 4, z) is seen past the
// wall when the segment crosses height 2 at x >= 0, (x + l) / 2 >= 0. So the share of the
// light seen is the share of l in [-0.5, 0.5] with l >= -x: 0.5 + x, within [0, 1].
const char* kEdgeScene = R"({"camera": {"eye": [0, 9, 0], "target": [0, 0, 0], "up": [0, 0, -1]},
  "shading": "whitted",
  "lights": [{"type": "parallelogram", "corner": [-0.5, 4, -0.5], "edge_a": [1, 0, 0], "edge_b": [0, 0, 1]}],
  "surfaces": [{"type": "polygon", "vertices": [[-50, 2, -50], [-50, 2, 50], [0, 2, 50], [0, 2, -50]]}]})";

double seen_share(const Scene& scene, const Vec3& p, int samples, std::uint64_t pixel) {
    const Light& light = scene.lights[0];
    Sampler s(3, pixel);
    const int side = int(std::lround(std::sqrt(double(samples))));
    s.set_strata(samples, side, Strata::jittered);
    int seen = 0;
    for (int k = 0; k < samples; ++k) {
        s.start_sample(k);
        const Vec3 q = light_point(light, sample_square(s, Dimension::light));
        seen += !scene.occluded(Ray{p, q - p}, Interval{Real(1e-4), Real(1 - 1e-4)});
    }
    return double(seen) / samples;
}

}  // namespace

TEST_CASE("the share of a light seen past an edge: analytic, across the penumbra") {
    Scene scene = rt::test::scene_text(kEdgeScene, AccelKind::none);
    std::uint64_t pixel = 0;
    for (double x : {-0.7, -0.45, -0.2, 0.0, 0.1, 0.3, 0.48, 0.6}) {
        CAPTURE(x);
        const double want = std::clamp(0.5 + x, 0.0, 1.0);
        // 64 x 64 strata: only the column of strata the boundary l = -x crosses is uncertain.
        CHECK(std::abs(seen_share(scene, Vec3(x, 0, 0), 4096, ++pixel) - want) < 1.0 / 64 + 1e-9);
    }
}

TEST_CASE("a soft shadow on the floor: the pixel's brightness follows the share of the light seen") {
    // The same scene with a floor, seen through an orthographic camera from 45 degrees on the
    // side away from the wall (so that the wall hides none of the penumbra). With no ambient
    // light, a floor pixel at x is Lambert's term times the share of the light it sees. The
    // light is 4 units above and 1 wide: its cosine varies by under 1.6 % across it.
    std::string text = kEdgeScene;
    text.replace(text.find("\"camera\""), text.find("\"shading\"") - text.find("\"camera\""),
                 R"("camera": {"projection": "orthographic", "eye": [10, 10, 0], "target": [0, 0, 0],
                   "window_height": 2}, )");
    text.replace(text.find("\"surfaces\": ["), 13,
                 R"("surfaces": [{"type": "polygon", "vertices": [[-9, 0, -9], [-9, 0, 9], [9, 0, 9], [9, 0, -9]]}, )");
    Scene scene = rt::test::scene_text(text);
    const RenderOptions o = rt::test::jittered(2, 48, 256);
    const Image img = render(scene, o).image;
    const View view = scene.camera.view(o.width, o.height);
    int floor_pixels = 0, failures = 0;
    for (int j = 0; j < o.height; ++j) {
        HitRecord rec;
        if (!scene.hit(view.pixel_ray(0, j), Interval{}, rec) || rec.surface != 0) continue;  // the wall
        const double x = rec.p.x;
        const double share = std::clamp(0.5 + x, 0.0, 1.0);
        // Lambert from the light's centre (0, 4, 0): cos = 4 / sqrt(16 + x^2); the default
        // diffuse colour 0.7 and light colour 1.
        const double lambert = 0.7 * 4 / std::sqrt(16 + x * x);
        CAPTURE(x);
        RT_CHECK_FIRST(failures,
                       std::abs(double(img.at(0, o.height - 1 - j).r) - share * lambert) < 0.02 * lambert + 0.015);
        floor_pixels += std::abs(x) < 0.5;  // in the penumbra
    }
    CHECK(failures == 0);
    CHECK(floor_pixels >= 10);
}

TEST_CASE("--stats: a point light draws no light sample; a parallelogram one per shading point") {
    Scene scene = rt::test::scene_text(kEdgeScene);
    const RenderOptions o = rt::test::jittered(8, 6, 4);
    const RenderResult area = render(scene, o);
    CHECK(area.counters.draws[std::size_t(Dimension::light)] > 0);
    CHECK(area.counters.draws[std::size_t(Dimension::lens)] == 0);
    CHECK(area.counters.draws[std::size_t(Dimension::time)] == 0);
    CHECK(area.counters.draws[std::size_t(Dimension::glossy)] == 0);
    scene.lights[0] = scene.lights[0].at(Vec3(0, 4, 0));  // the same light, shrunk to its centre
    const RenderResult point = render(scene, o);
    CHECK(point.counters.draws[std::size_t(Dimension::light)] == 0);
    CHECK(point.counters.of(RayKind::shadow) == area.counters.of(RayKind::shadow));  // one shadow ray each
}
