// Chapter 17: glossy reflection (course §9.11.4). The perturbed direction is the mirror
// direction moved within the square of the given width square to it: its offsets have the
// mean and spread of a uniform square; the share of directions left above a surface at a
// grazing angle is analytic, and so is the light a glossy mirror loses there.
#include "io/scene_file.hpp"
#include "render/render.hpp"
#include "shading/optics.hpp"
#include "support.hpp"
#include "support/small_render.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace rt;

TEST_CASE("17.1 glossy_direction: the mirror direction moved across a square of the given width") {
    // The middle of the square is the mirror direction itself.
    const Vec3 r = glm::normalize(Vec3(0.3, 0.8, -0.52));
    const Vec3 mid = glossy_direction(r, Real(0.5), Vec2(0.5, 0.5));
    CHECK(glm::length(mid - r) < 1e-6);
    // Worked values in the course's frame for r = +z: u = (0, -1, 0), v = (1, 0, 0).
    const Vec3 z(0, 0, 1);
    const Vec3 g = glossy_direction(z, Real(0.2), Vec2(0.75, 0.25));
    CAPTURE(g);
    CHECK(g.x == doctest::Approx(-0.05));
    CHECK(g.y == doctest::Approx(-0.05));
    CHECK(g.z == doctest::Approx(1));
    // Over an even grid: every offset square to r, the offsets centred on r, with the spread
    // of a uniform square of side a: E|offset|^2 = a^2 / 6; corners a / sqrt(2) away.
    for (Real a : {Real(0.05), Real(0.3), Real(1.5)}) {
        const int n = 64;
        double mean_x = 0, mean_y = 0, mean_z = 0, spread = 0, farthest = 0;
        int failures = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const Vec2 uv((i + 0.5) / n, (j + 0.5) / n);
                const Vec3 off = glossy_direction(r, a, uv) - r;
                CAPTURE(a);
                CAPTURE(uv);
                CAPTURE(off);
                RT_CHECK_FIRST(failures, std::abs(glm::dot(off, r)) < 1e-5);  // square to r
                mean_x += off.x, mean_y += off.y, mean_z += off.z;
                spread += glm::dot(off, off);
                farthest = std::max(farthest, double(glm::length(off)));
            }
        CHECK(failures == 0);
        CAPTURE(a);
        CHECK(std::abs(mean_x) / (n * n) < 1e-5);
        CHECK(std::abs(mean_y) / (n * n) < 1e-5);
        CHECK(std::abs(mean_z) / (n * n) < 1e-5);
        CHECK(spread / (n * n) == doctest::Approx(a * a / 6).epsilon(0.01));
        CHECK(farthest == doctest::Approx(a * (1 - 1.0 / n) / std::sqrt(2)).epsilon(1e-4));
    }
}

TEST_CASE("at a grazing angle, the share of glossy directions above the surface is analytic") {
    // r = (cos t, sin t, 0) leaves a floor y = 0 at angle t. The course's frame puts u =
    // (-sin t, cos t, 0) and v = (0, 0, 1), so r' . y = sin t + (s - 1/2) a cos t for s
    // uniform in [0, 1): above the floor for s > 1/2 - tan t / a.
    for (double degrees : {2.0, 5.0, 10.0, 30.0}) {
        for (double a : {0.1, 0.4}) {
            const double t = degrees * std::numbers::pi / 180;
            const Vec3 r(std::cos(t), std::sin(t), 0);
            const int n = 256;
            int above = 0;
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j)
                    above += glossy_direction(r, Real(a), Vec2((i + 0.5) / n, (j + 0.5) / n)).y > 0;
            CAPTURE(degrees);
            CAPTURE(a);
            CHECK(double(above) / (n * n) ==
                  doctest::Approx(std::clamp(0.5 + std::tan(t) / a, 0.0, 1.0)).epsilon(0.01));
        }
    }
}

TEST_CASE("a glossy mirror at a grazing angle loses the light of the directions below it") {
    // An orthographic camera looks at a glossy floor from 5 degrees above it; the sky is
    // white, the floor black but for its mirror colour 1. Each pixel is the share of glossy
    // directions that stay above the floor (they see the sky; the rest bring back black).
    const double t = 5 * std::numbers::pi / 180;
    const std::string text = R"({"camera": {"projection": "orthographic", "eye": [-10, )" +
                             std::to_string(10 * std::tan(t)) + R"(, 0], "target": [0, 0, 0], "window_height": 0.1},
      "shading": "whitted", "background": [1, 1, 1],
      "materials": {"floor": {"diffuse": [0, 0, 0], "mirror": [1, 1, 1], "glossy": 0.4}},
      "surfaces": [{"type": "polygon", "vertices": [[-50, 0, -50], [-50, 0, 50], [50, 0, 50], [50, 0, -50]],
                    "material": "floor"}]})";
    Scene scene = rt::test::scene_text(text);
    const RenderOptions o = rt::test::jittered(4, 4, 1024);
    const RenderResult r = render(scene, o);
    const double want = 0.5 + std::tan(t) / 0.4;  // 0.719
    for (int y = 1; y < 3; ++y)                   // rows that see the floor (the window straddles it)
        for (int x = 0; x < 4; ++x) CHECK(double(r.image.at(x, y).r) == doctest::Approx(want).epsilon(0.02));
    CHECK(r.counters.draws[std::size_t(Dimension::glossy)] > 0);
    // A sharp mirror draws no glossy sample, and loses nothing.
    scene.materials[1].glossy = 0;
    const RenderResult sharp = render(scene, o);
    CHECK(sharp.counters.draws[std::size_t(Dimension::glossy)] == 0);
    CHECK(sharp.image.at(1, 1).r == doctest::Approx(1));
}
