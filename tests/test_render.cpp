// The render loop's guarantees: a budget refused before any work, only finite pixels, exact
// averages of identical samples, and no random numbers drawn for what a scene does not use.
#include "io/scene_file.hpp"
#include "render/integrators.hpp"
#include "render/render.hpp"
#include "support.hpp"

#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>

using namespace rt;

TEST_SUITE("common") {
TEST_CASE("--stats: nothing moving draws no time sample") {
    const char* text = R"({"camera": {"eye": [0, 0, 3], "target": [0, 0, 0]},
      "surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]})";
    Scene scene = load_scene_text(text, "still.json", ".");
    scene.build_accel(AccelKind::fast);
    CHECK_FALSE(scene.surfaces.moves());
    RenderOptions o;
    o.width = 8;
    o.height = 6;
    o.spp = 4;
    const RenderResult r = render(scene, o);
    CHECK(r.counters.draws[std::size_t(Dimension::time)] == 0);
    CHECK(r.counters.draws[std::size_t(Dimension::lens)] == 0);
    CHECK(r.counters.draws[std::size_t(Dimension::light)] == 0);
}

TEST_CASE("render budget: image size and samples refused before any work") {
    RenderOptions o;
    CHECK_NOTHROW(check_budget(o));
    o.width = 16384;
    o.height = 2048;
    CHECK_NOTHROW(check_budget(o));
    o.height = 2049;
    CHECK_THROWS_WITH_AS(check_budget(o), "--width x --height: image size must be in 1..33554432 pixels, not 33570816",
                         std::invalid_argument);
    o.height = 2048;
    o.spp = 129;
    CHECK_THROWS_AS(check_budget(o), std::invalid_argument);
}

namespace {
// An integrator that returns NaN or infinity on some pixels, as a broken exercise might.
class Broken : public Integrator {
public:
    Color Li(const Scene&, const Ray& ray, TraceContext&) const override {
        if (ray.direction.x > 0) return Color(std::numeric_limits<float>::quiet_NaN(), 0, 0);
        if (ray.direction.y > 0) return Color(std::numeric_limits<float>::infinity());
        return Color(0.5f);
    }
};
}  // namespace

TEST_CASE("the render loop writes only finite pixels and counts the samples it left out") {
    Scene scene;
    scene.camera.eye = Vec3(0, 0, 5);
    scene.camera.target = Vec3(0);
    scene.integrator = std::make_shared<Broken>();
    RenderOptions o;
    o.width = 8;
    o.height = 6;
    o.spp = 2;
    const RenderResult r = render(scene, o);
    std::size_t finite = 0;
    for (const Color& c : r.image.pixels) finite += std::isfinite(c.r + c.g + c.b);
    CHECK(finite == r.image.pixels.size());
    // Right half (x > 0): NaN; top-left quarter: infinite; both left out of their pixel.
    CHECK(r.counters.nonfinite_samples > 0);
    CHECK(r.counters.nonfinite_samples < std::uint64_t(8 * 6 * 2));
    CHECK(r.image.at(0, 5) == Color(0.5f));  // bottom left: every sample finite
}

TEST_CASE("one sample at each pixel's centre: the integrator's tile is what the general loop makes") {
    // With the random pattern and one sample, render() hands each tile to the integrator
    // (Integrator::trace_centre_tile); the regular pattern's one sample sits at the same
    // centre but goes through the general loop (camera_sample, the sum). Same pixels, bit for
    // bit, and the same counts of rays: for a FirstHitIntegrator (Whitted, with mirrors and
    // shadows), whose camera rays the tile searches eight at a time as packets (book §10.5),
    // and for an integrator that only has Li, where some samples are not finite. The search
    // work differs where packets were used: fewer boxes tested for the same hits.
    Scene whitted = load_scene_text(R"({"camera": {"eye": [0, 1, 6], "target": [0, 0, 0]}, "shading": "whitted",
        "materials": {"mirror": {"diffuse": [0.1, 0.1, 0.1], "mirror": [0.8, 0.8, 0.8]}},
        "lights": [{"type": "point", "position": [3, 5, 4], "color": [1, 1, 1]}],
        "surfaces": [{"type": "sphere", "center": [-0.8, 0, 0], "radius": 0.7, "material": "mirror"},
                     {"type": "sphere", "center": [0.9, 0, 0], "radius": 0.6},
                     {"type": "sphere", "center": [0, -100.7, 0], "radius": 100}]})",
                                    "whitted.json", ".");
    whitted.build_accel(AccelKind::fast);
    Scene broken = whitted;
    broken.integrator = std::make_shared<Broken>();
    for (const Scene* scene : {&whitted, &broken}) {
        RenderOptions o;
        o.width = 37;  // tiles cut short on the right and at the bottom
        o.height = 21;
        const RenderResult centre = render(*scene, o);
        o.antialiasing.pattern = PixelPattern::regular;
        const RenderResult general = render(*scene, o);
        for (std::size_t k = 0; k < centre.image.pixels.size(); ++k) {
            const Color a = centre.image.pixels[k], b = general.image.pixels[k];
            CHECK(std::bit_cast<std::array<std::uint32_t, 3>>(a) == std::bit_cast<std::array<std::uint32_t, 3>>(b));
        }
        CHECK(centre.counters.rays == general.counters.rays);
        CHECK(centre.counters.nonfinite_samples == general.counters.nonfinite_samples);
        if (scene == &broken)
            CHECK(centre.counters.nodes_visited == general.counters.nodes_visited);
        else
            CHECK(centre.counters.nodes_visited < general.counters.nodes_visited);
    }
    RenderOptions o;
    o.width = 37;
    o.height = 21;
    const RenderResult w = render(whitted, o);
    CHECK(w.counters.of(RayKind::camera) == 37u * 21u);
    CHECK(w.counters.of(RayKind::reflection) > 0);
    CHECK(w.counters.of(RayKind::shadow) > 0);
    CHECK(render(broken, o).counters.nonfinite_samples > 0);
}

TEST_CASE("the average of identical samples is that sample, at the most samples per pixel allowed") {
    // A float sum of 65536 copies of 0.7 comes out 7e-4 off (the sum's step outgrows the
    // sample): each pixel must be the background exactly, every channel, bit for bit.
    Scene scene = load_scene_text(R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0]},
        "background": [0.6, 0.7, 0.85], "surfaces": [{"type": "sphere", "center": [0, 0, 50], "radius": 1}]})",
                                  "background.json", ".");
    REQUIRE(scene.background == Color(0.6f, 0.7f, 0.85f));
    RenderOptions o;
    o.width = 2;
    o.height = 2;
    o.spp = int(limits::samples_per_pixel.max);
    const RenderResult r = render(scene, o);
    for (const Color& c : r.image.pixels) {
        CHECK(c.r == 0.6f);
        CHECK(c.g == 0.7f);
        CHECK(c.b == 0.85f);
    }
}

TEST_CASE("progressive passes: a pass takes its samples' strata, and a cancelled pass does no work") {
    // The explorer renders one sample per pass (RenderOptions::first_sample): with the
    // regular pattern no random number places a sample, so the passes' mean is the render.
    Scene scene = look_at(Vec3(0, 0, 5), Vec3(0), 40, std::make_shared<RayDirectionIntegrator>());
    RenderOptions o;
    o.width = 5;
    o.height = 3;
    o.spp = 4;
    o.antialiasing.pattern = PixelPattern::regular;
    const RenderResult whole = render(scene, o);
    std::vector<glm::dvec3> sum(whole.image.pixels.size(), glm::dvec3(0));
    for (int k = 0; k < o.spp; ++k) {
        RenderOptions pass = o;
        pass.first_sample = k;
        pass.sample_count = 1;
        const RenderResult r = render(scene, pass);
        CHECK(r.counters.total() == std::uint64_t(o.width * o.height));  // one camera ray a pixel
        for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += glm::dvec3(r.image.pixels[i]);
        if (k == 0) CHECK(r.image.pixels[0] != whole.image.pixels[0]);  // one stratum is not four
    }
    for (std::size_t i = 0; i < sum.size(); ++i)
        for (int c = 0; c < 3; ++c) CHECK(sum[i][c] / o.spp == doctest::Approx(whole.image.pixels[i][c]).epsilon(1e-6));

    RenderOptions bad = o;
    bad.first_sample = 3;
    bad.sample_count = 2;
    CHECK_THROWS_WITH_AS(render(scene, bad), "samples 3+2 are not samples of a 4-sample pixel", std::invalid_argument);

    std::atomic<bool> cancel{true};
    RenderOptions cancelled = o;
    cancelled.cancel = &cancel;
    const RenderResult none = render(scene, cancelled);
    CHECK(none.counters.total() == 0);
    CHECK(none.image.pixels[0] == Color(0));
}
}  // TEST_SUITE("common")
