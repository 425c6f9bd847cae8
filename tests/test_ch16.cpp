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
#include <numbers>
#include <vector>

using namespace rt;

TEST_CASE("16.1 lens_point: the square lens is 2u - 1, centred on the lens") {
    CHECK(lens_point(Vec2(0.5, 0.5), LensShape::square) == Vec2(0, 0));
    CHECK(lens_point(Vec2(0, 0), LensShape::square) == Vec2(-1, -1));
    CHECK(lens_point(Vec2(0.75, 0.25), LensShape::square) == Vec2(0.5, -0.5));
    CHECK(lens_point(Vec2(0.125, 0.875), LensShape::square) == Vec2(-0.75, 0.75));
}

namespace {

// Where lens_point(u, disk) puts an even 512 x 512 grid of u: in which of 48 cells of equal
// area (4 rings between radii sqrt(k / 4), 12 sectors of 30 degrees starting at 10 degrees,
// so that no cell edge lies on the concentric map's diagonals), the mean, and the farthest
// point from the centre.
struct DiskCells {
    static constexpr int rings = 4, sectors = 12, n = 512;
    std::vector<int> count = std::vector<int>(rings * sectors);
    Vec2 mean{0};
    double farthest = 0;
    Vec2 farthest_u{0}, farthest_p{0};
};

DiskCells disk_cells() {
    DiskCells c;
    double sx = 0, sy = 0;
    for (int i = 0; i < c.n; ++i)
        for (int j = 0; j < c.n; ++j) {
            const Vec2 u(Real((i + 0.5) / c.n), Real((j + 0.5) / c.n));
            const Vec2 p = lens_point(u, LensShape::disk);
            const double r2 = double(glm::dot(p, p));
            if (std::sqrt(r2) > c.farthest) c.farthest = std::sqrt(r2), c.farthest_u = u, c.farthest_p = p;
            sx += double(p.x), sy += double(p.y);
            const int ring = std::clamp(int(r2 * c.rings), 0, c.rings - 1);
            double angle = std::atan2(double(p.y), double(p.x)) - 10 * std::numbers::pi / 180;
            if (angle < 0) angle += 2 * std::numbers::pi;
            const int sector = std::clamp(int(angle / (2 * std::numbers::pi) * c.sectors), 0, c.sectors - 1);
            ++c.count[std::size_t(ring * c.sectors + sector)];
        }
    c.mean = Vec2(Real(sx / (c.n * c.n)), Real(sy / (c.n * c.n)));
    return c;
}

}  // namespace

TEST_CASE("16.1 lens_point: the disk lens is the unit disk, centred and uniform") {
    // Any map with these properties will do, in any orientation (the concentric map of
    // §16.2 mirrored or turned is as good as the reference).
    const DiskCells c = disk_cells();
    CAPTURE(c.farthest_u);
    CAPTURE(c.farthest_p);
    CHECK(c.farthest <= 1 + 1e-6);  // inside the unit disk
    CHECK(c.farthest >= 0.99);      // and out to its rim
    CAPTURE(c.mean);
    CHECK(glm::length(c.mean) < 1e-3);  // centred on the lens's middle
    // Uniform: equal areas of u to equal areas of the disk, so each cell holds 1/48 of the
    // grid. An even grid does that far better than random points would: the concentric map
    // is within 0.9 % in every cell; a polar map with radius u (not sqrt u) puts twice the
    // share in the inner ring, and one whose radius is off by a power of 1.2 errs by 27 %.
    const double share = double(c.n) * c.n / (c.rings * c.sectors);
    int failures = 0;
    for (int ring = 0; ring < c.rings; ++ring)
        for (int sector = 0; sector < c.sectors; ++sector) {
            const int count = c.count[std::size_t(ring * c.sectors + sector)];
            const double radii[2] = {std::sqrt(ring / 4.0), std::sqrt((ring + 1) / 4.0)};
            const double degrees[2] = {10 + 30.0 * sector, 40 + 30.0 * sector};
            CAPTURE(radii);
            CAPTURE(degrees);
            CAPTURE(count);
            CAPTURE(share);
            RT_CHECK_FIRST(failures, std::abs(count - share) < 0.03 * share);
        }
    CHECK(failures == 0);
}

TEST_CASE("16.1 lens_point: the disk keeps each stratum of u compact") {
    // Each stratum of a 4 x 4 pattern of u must land in one small patch of the disk, so that
    // stratified u stay stratified on the lens: no two of its points more than 1 apart. The
    // concentric map's widest patch is 0.77 across; the polar map's outer arcs are 1.41
    // (a quarter turn of the rim), which is why §16.2 does not use it.
    int failures = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            std::vector<std::pair<Vec2, Vec2>> points;  // u, p
            for (int a = 0; a <= 8; ++a)
                for (int b = 0; b <= 8; ++b) {
                    const Vec2 u(Real((i + a / 8.0 * 0.999) / 4), Real((j + b / 8.0 * 0.999) / 4));
                    points.push_back({u, lens_point(u, LensShape::disk)});
                }
            for (const auto& [u1, p1] : points)
                for (const auto& [u2, p2] : points) {
                    const Vec2 u = u1, v = u2, p = p1, q = p2;  // named copies: clang 14 cannot capture a binding
                    CAPTURE(u);
                    CAPTURE(p);
                    CAPTURE(v);
                    CAPTURE(q);
                    RT_CHECK_FIRST(failures, glm::length(p - q) < 1);
                }
        }
    CHECK(failures == 0);
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
