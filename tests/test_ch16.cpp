// Chapter 16: depth of field (course §9.11.3). Lens points on worked values (square and
// disk, centred, strata kept apart); the thin-lens ray meets the pinhole ray on the plane
// in focus, and spreads by the thin-lens formula off it; an edge behind the plane in focus
// renders as the ramp that formula predicts; no lens sample without an aperture.
#include "io/scene_file.hpp"
#include "render/render.hpp"
#include "support.hpp"
#include "support/small_render.hpp"

#include <algorithm>
#include <cmath>

using namespace rt;

TEST_CASE("16.1 lens_point: the square [-1, 1]^2 and the unit disk, centred on the lens") {
    CHECK(lens_point(Vec2(0.5, 0.5), LensShape::square) == Vec2(0, 0));
    CHECK(lens_point(Vec2(0, 0), LensShape::square) == Vec2(-1, -1));
    CHECK(lens_point(Vec2(0.75, 0.25), LensShape::square) == Vec2(0.5, -0.5));
    CHECK(lens_point(Vec2(0.5, 0.5), LensShape::disk) == Vec2(0, 0));
    // Concentric: the square's ring of half-width r goes to the circle of radius r.
    const Vec2 right = lens_point(Vec2(0.75, 0.5), LensShape::disk);
    CHECK(right.x == doctest::Approx(0.5));
    CHECK(right.y == doctest::Approx(0).epsilon(1e-6));
    const Vec2 top = lens_point(Vec2(0.5, 0.875), LensShape::disk);
    CHECK(top.x == doctest::Approx(0).epsilon(1e-6));
    CHECK(top.y == doctest::Approx(0.75));
    const Vec2 corner = lens_point(Vec2(1, 1), LensShape::disk);  // the square's corner: 45 degrees
    CHECK(corner.x == doctest::Approx(std::sqrt(0.5)));
    CHECK(corner.y == doctest::Approx(std::sqrt(0.5)));
    // Over an even grid of u: inside the disk, centred, and uniform (mean |p|^2 = 1/2 for a
    // uniform unit disk; 1 - the share within radius 1/2 = 3/4).
    const int n = 200;
    double sx = 0, sy = 0, r2 = 0, inner = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const Vec2 p = lens_point(Vec2((i + 0.5) / n, (j + 0.5) / n), LensShape::disk);
            CHECK(glm::length(p) <= 1 + 1e-6);
            sx += p.x, sy += p.y, r2 += glm::dot(p, p), inner += glm::length(p) < 0.5;
        }
    CHECK(std::abs(sx) / (n * n) < 1e-6);
    CHECK(std::abs(sy) / (n * n) < 1e-6);
    CHECK(r2 / (n * n) == doctest::Approx(0.5).epsilon(0.01));
    CHECK(inner / (n * n) == doctest::Approx(0.25).epsilon(0.02));
    // Neighbouring u give neighbouring points: the strata of a 4 x 4 pattern stay compact.
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const Vec2 a = lens_point(Vec2(i / 4.0 + 0.01, j / 4.0 + 0.01), LensShape::disk);
            const Vec2 b = lens_point(Vec2(i / 4.0 + 0.24, j / 4.0 + 0.24), LensShape::disk);
            CHECK(glm::length(a - b) < 0.8);
        }
}

namespace {

Basis axes() {
    return Basis{Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
}

// Where the ray reaches the plane at distance z in front of an eye at the origin looking down -z.
Vec3 at_depth(const Ray& r, Real z) {
    const Real t = (-z - r.origin.z) / r.direction.z;
    return r.at(t);
}

}  // namespace

TEST_CASE("16.2 thin_lens_ray: sharp on the plane in focus, spread by the thin-lens formula off it") {
    const Vec3 eye(0);
    const Real d = 1, aperture = Real(0.4), focus = 5;
    const Vec2 uv(Real(0.1), Real(-0.05));
    const Ray pinhole = perspective_ray(eye, axes(), d, uv);
    // The middle of the lens is the pinhole.
    const Ray middle = thin_lens_ray(eye, axes(), d, uv, aperture, focus, Vec2(0));
    CHECK(glm::length(middle.origin - eye) < 1e-6);
    CHECK(glm::length(glm::normalize(middle.direction) - glm::normalize(pinhole.direction)) < 1e-6);
    const Vec3 sharp = at_depth(pinhole, focus);
    for (const Vec2 lens : {Vec2(1, 1), Vec2(-1, 0.3), Vec2(0.5, -1), Vec2(-1, -1)}) {
        const Ray r = thin_lens_ray(eye, axes(), d, uv, aperture, focus, lens);
        CAPTURE(lens);
        // Starts on the lens (in the plane of u and v, within half the aperture of the eye).
        CHECK(r.origin.z == doctest::Approx(0));
        CHECK(r.origin.x == doctest::Approx(aperture / 2 * lens.x));
        CHECK(r.origin.y == doctest::Approx(aperture / 2 * lens.y));
        // Meets the pinhole ray on the plane in focus.
        CHECK(glm::length(at_depth(r, focus) - sharp) < 1e-5);
        // At depth z it lands (aperture / 2)(1 - z / focus) lens away from the pinhole ray:
        // the blur of a point at z is the lens scaled by |1 - z / focus| (the thin-lens formula).
        for (Real z : {Real(2.5), Real(10), Real(20)}) {
            const Vec3 off = at_depth(r, z) - at_depth(pinhole, z);
            CHECK(off.x == doctest::Approx(aperture / 2 * lens.x * (1 - z / focus)).epsilon(1e-5));
            CHECK(off.y == doctest::Approx(aperture / 2 * lens.y * (1 - z / focus)).epsilon(1e-5));
        }
    }
}

TEST_CASE("an edge twice as far as the plane in focus: the ramp the thin-lens formula predicts") {
    // A white half-plane x < 0 at depth 10 on black, a square lens 0.4 wide focused at 5: a
    // pixel whose pinhole ray meets depth 10 at x sees the half-plane through the share of the
    // lens whose rays land at x - 0.2 l_x < 0 (l_x uniform in [-1, 1]): clamp(1/2 - x / 0.4).
    const char* text = R"({"camera": {"eye": [0, 0, 0], "target": [0, 0, -1], "fov": 0.11459,
        "aperture": 0.4, "focus_distance": 5}, "ambient": [1, 1, 1], "background": [0, 0, 0],
      "materials": {"white": {"diffuse": [1, 1, 1]}},
      "surfaces": [{"type": "polygon", "vertices": [[-50, -50, -10], [0, -50, -10], [0, 50, -10], [-50, 50, -10]],
                    "material": "white"}]})";
    Scene scene = rt::test::scene_text(text, AccelKind::none);
    const RenderOptions o = rt::test::jittered(100, 2, 1024);
    const Image img = render(scene, o).image;
    const View view = scene.camera.view(o.width, o.height);
    int failures = 0;
    for (int i = 0; i < o.width; ++i) {
        const Real x = at_depth(view.pixel_ray(i, 0), 10).x;
        const double want = std::clamp(0.5 - double(x) / 0.4, 0.0, 1.0);
        CAPTURE(i);
        CAPTURE(x);
        RT_CHECK_FIRST(failures, std::abs(double(img.at(i, 0).r) - want) < 0.03);
    }
    CHECK(failures == 0);
    // The same edge on the plane in focus is sharp: one pixel between black and white.
    std::string sharp = text;
    sharp.replace(sharp.find("\"focus_distance\": 5"), 19, "\"focus_distance\": 10");
    Scene focused = rt::test::scene_text(sharp, AccelKind::none);
    const Image crisp = render(focused, o).image;
    int between = 0;
    for (int i = 0; i < o.width; ++i) between += crisp.at(i, 0).r > 0.01f && crisp.at(i, 0).r < 0.99f;
    CHECK(between <= 1);
}

TEST_CASE("--stats: no lens sample without an aperture; one per camera ray with one") {
    const char* text = R"({"camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "aperture": 0.2},
      "surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]})";
    Scene scene = rt::test::scene_text(text);
    RenderOptions o;
    o.width = 8;
    o.height = 6;
    o.spp = 4;
    const RenderResult with = render(scene, o);
    CHECK(with.counters.draws[std::size_t(Dimension::lens)] == with.counters.of(RayKind::camera) * 2);
    scene.camera.aperture = 0;
    const RenderResult without = render(scene, o);
    CHECK(without.counters.draws[std::size_t(Dimension::lens)] == 0);
    CHECK(without.counters.draws[std::size_t(Dimension::time)] == 0);
}

TEST_CASE("thin_lens_ray far from the origin: every lens ray still meets the plane in focus") {
    // A camera 37,000 units from the origin, looking along (1, 2, 2): the lens rays of one
    // window point must meet where the pinhole ray meets the plane in focus, to the rounding
    // of coordinates that size (a few units in the last place of 37,000), in float as in double.
    const Vec3 eye(30000, -20000, 10000);
    const Vec3 w = glm::normalize(Vec3(1, 2, 2));
    const Vec3 u = glm::normalize(glm::cross(Vec3(0, 0, 1), w));
    const Basis b{u, glm::cross(w, u), w};
    const Real d = Real(0.5), focus = 40, aperture = 3;
    const Vec2 uv(Real(0.13), Real(-0.21));
    const Ray pinhole = perspective_ray(eye, b, d, uv);
    const Vec3 sharp = pinhole.at(focus / d);
    const Real tolerance = 64 * rt::test::kEps * glm::length(eye);
    for (int i = 0; i <= 4; ++i)
        for (int j = 0; j <= 4; ++j) {
            const Vec2 lens(Real(i) / 2 - 1, Real(j) / 2 - 1);
            const Ray r = thin_lens_ray(eye, b, d, uv, aperture, focus, lens);
            CAPTURE(lens);
            CHECK(glm::length(r.at(focus / d) - sharp) < tolerance);
            CHECK(glm::length(r.origin - eye) <= aperture / 2 * Real(1.4143) + tolerance);
        }
}
