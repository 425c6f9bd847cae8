// Chapter 05: the ray tracing program (course §9.4-9.4.1): closest hit, shading, scene files.
#include "accel/surface_list.hpp"
#include "geometry/polygon.hpp"
#include "geometry/sphere.hpp"
#include "io/scene_file.hpp"
#include "render/integrators.hpp"
#include "render/render.hpp"
#include "support.hpp"
#include "support/source_dir.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <pcg_random.hpp>
#include <random>

using namespace rt;
namespace fs = std::filesystem;

namespace {

const std::string kScenes = rt::test::source_dir() + "/chapters/ch05_ray_tracing_program/scenes/";

}  // namespace

TEST_SUITE("ch05") {
TEST_CASE("5.1 SurfaceList::hit returns the closest hit in the interval, whatever the order") {
    for (bool near_first : {true, false}) {
        SurfaceList list;
        const Sphere near(Vec3(0, 0, -3), 1), far(Vec3(0, 0, -10), 2);
        const SurfaceId a = list.add(near_first ? near : far, 1, "a");
        const SurfaceId b = list.add(near_first ? far : near, 2, "b");
        const SurfaceId near_id = near_first ? a : b, far_id = near_first ? b : a;
        HitRecord rec;
        const Ray r{Vec3(0), Vec3(0, 0, -1)};
        REQUIRE(list.hit(r, Interval{}, rec));
        CHECK(rec.surface == near_id);
        CHECK(rec.material == list[near_id].material);
        CHECK(rec.t == doctest::Approx(2));
        REQUIRE(list.hit(r, Interval{4.5, kInfinity}, rec));  // past the near sphere
        CHECK(rec.surface == far_id);
        CHECK(rec.t == doctest::Approx(8));
        // A miss leaves the record alone: the caller's own hit (here a made-up one) survives.
        HitRecord untouched;
        untouched.t = Real(1.25);
        untouched.surface = 7;
        untouched.material = 5;
        CHECK_FALSE(list.hit(r, Interval{0, 1.5}, untouched));
        CHECK(untouched.t == Real(1.25));
        CHECK(untouched.surface == 7);
        CHECK(untouched.material == 5);
        CHECK(list.bounding_box().min.z == doctest::Approx(-12));
    }
    HitRecord rec;
    CHECK_FALSE(SurfaceList().hit(Ray{Vec3(0), Vec3(1, 0, 0)}, Interval{}, rec));
}

TEST_CASE("5.1 at exactly equal t the later surface in the list wins (the header's rule)") {
    // Two copies of one sphere, and two of one square: every ray meets each pair at the same t,
    // to the bit. Shrinking max to each hit's t (the interval closed) keeps the later one;
    // the acceleration structures of chapters 10-12 rank the earlier one first (book §5.3).
    for (int copies : {2, 3}) {
        SurfaceList list;
        for (int k = 0; k < copies; ++k) list.add(Sphere(Vec3(0, 0, -4), 1), MaterialId(k + 1));
        for (int k = 0; k < copies; ++k)
            list.add(Polygon({Vec3(2, -1, -6), Vec3(4, -1, -6), Vec3(4, 1, -6), Vec3(2, 1, -6)}), MaterialId(k + 10));
        HitRecord rec;
        CAPTURE(copies);
        REQUIRE(list.hit(Ray{Vec3(0), Vec3(0, 0, -1)}, Interval{}, rec));
        CHECK(rec.t == doctest::Approx(3));
        CHECK(rec.surface == SurfaceId(copies - 1));
        CHECK(rec.material == MaterialId(copies));
        REQUIRE(list.hit(Ray{Vec3(0), Vec3(3, 0, -6)}, Interval{}, rec));
        CHECK(rec.t == doctest::Approx(1));
        CHECK(rec.surface == SurfaceId(2 * copies - 1));
        CHECK(rec.material == MaterialId(copies + 9));
    }
}

TEST_CASE("5.1 no field of a farther hit survives in the closest one") {
    // The bug this architecture removes: a mesh hit found first, then a nearer sphere. The
    // record must be the sphere's alone, with no triangle index or barycentrics left over.
    const Scene scene = load_scene_text(R"({"camera": {"eye": [0,0,5], "target": [0,0,0]}, "shading": "barycentric",
        "surfaces": [{"type": "icosphere", "center": [0,0,-2], "radius": 1, "subdivisions": 1},
                     {"type": "sphere", "center": [0,0,0], "radius": 0.5}]})",
                                        "stale.json", ".");
    RenderOptions o;
    o.width = 41;
    o.height = 41;
    const Pick p = pick(scene, o, 20, 20);
    REQUIRE(p.hit.has_value());
    CHECK(scene.surfaces.name(p.hit->surface) == "sphere 1");
    CHECK(p.hit->primitive == kNone);
    CHECK_FALSE(p.hit->has_barycentrics);
    CHECK(p.hit->t == doctest::Approx(4.5));
    // Shaded by barycentrics, the sphere in front of the mesh shows its normal, (0, 0, 1) at
    // the centre, not the colours of a triangle behind it.
    const Image img = render(scene, o).image;
    CHECK(img.at(20, 20).r == doctest::Approx(0.5));
    CHECK(img.at(20, 20).g == doctest::Approx(0.5));
    CHECK(img.at(20, 20).b == doctest::Approx(1));
    // Where only the mesh is seen, the barycentric colours sum to 1.
    const Color mesh_pixel = img.at(20, 14);
    CHECK(mesh_pixel.r + mesh_pixel.g + mesh_pixel.b == doctest::Approx(1).epsilon(1e-5));
}

TEST_CASE("any-hit: occluded agrees with the closest hit on every ray, and respects the interval") {
    Scene scene = load_scene_file(kScenes + "meshes.json");
    pcg32 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    const Box box = scene.surfaces.bounding_box();
    const Vec3 mid = (box.min + box.max) / Real(2), half = (box.max - box.min) / Real(2);
    int disagree = 0, hits = 0;
    for (int k = 0; k < 3000; ++k) {
        const Vec3 origin = mid + Real(2) * half * Vec3{Real(u(rng)), Real(u(rng)), Real(u(rng))};
        const Vec3 target = mid + half * Vec3{Real(u(rng)), Real(u(rng)), Real(u(rng))};
        const Ray r{origin, target - origin};
        HitRecord rec;
        const bool found = scene.hit(r, Interval{}, rec);
        hits += found;
        disagree += found != scene.occluded(r, Interval{});
        if (found) {
            // Nothing is in the way before the closest hit, and the hit itself is (the
            // margins allow for t's rounding).
            const Real t = rec.t;
            disagree += scene.occluded(r, Interval{0, t * Real(0.999)});
            disagree += !scene.occluded(r, Interval{0, t * Real(1.001)});
        }
    }
    CHECK(hits > 300);
    CHECK(disagree == 0);
    CHECK_FALSE(Scene().occluded(Ray{Vec3(0), Vec3(1, 0, 0)}, Interval{}));
}

TEST_CASE("5.2 lambert: c_r c_l max(0, n . l)") {
    const Vec3 n(0, 0, 1);
    const Color c = lambert(Color(0.5f, 0.25f, 1), Color(1, 2, 0.5f), n, glm::normalize(Vec3(0, 1, 1)));
    CHECK(c.r == doctest::Approx(0.5 * std::sqrt(0.5)));
    CHECK(c.g == doctest::Approx(0.5 * std::sqrt(0.5)));
    CHECK(c.b == doctest::Approx(0.5 * std::sqrt(0.5)));
    CHECK(lambert(Color(1), Color(1), n, Vec3(0, 0, -1)) == Color(0));  // light behind
}

TEST_CASE("5.3 blinn_phong_highlight: c_l c_p max(0, n . h)^p") {
    const Vec3 n(0, 0, 1);
    // l and v mirror each other about n: h = n, the full highlight.
    const Vec3 l = glm::normalize(Vec3(1, 0, 1)), v = glm::normalize(Vec3(-1, 0, 1));
    const Color full = blinn_phong_highlight(Color(0.5f), 10, Color(1, 0.5f, 2), n, l, v);
    CHECK(full.r == doctest::Approx(0.5));
    CHECK(full.g == doctest::Approx(0.25));
    CHECK(full.b == doctest::Approx(1));
    // Off the mirror direction: cos(angle between n and h)^p.
    const Vec3 v2 = glm::normalize(Vec3(0, 0, 1));
    const Vec3 h = glm::normalize(l + v2);
    CHECK(blinn_phong_highlight(Color(1), 8, Color(1), n, l, v2).r == doctest::Approx(std::pow(h.z, 8)).epsilon(1e-5));
    // A light behind the surface lights nothing, even with an even exponent.
    CHECK(blinn_phong_highlight(Color(1), 2, Color(1), n, Vec3(0, 0, -1), v) == Color(0));
}

TEST_CASE("5.3 no highlight from a light behind the surface, even where h tips to n's side") {
    // The light just below the surface's plane and the eye straight above: h = (l + v)/|l + v|
    // has n . h = 0.67 > 0, so max(0, n . h)^p alone would light it (0.67^2 = 0.45).
    const Vec3 n(0, 0, 1), below = glm::normalize(Vec3(1, 0, Real(-0.1))), above(0, 0, 1);
    CHECK(glm::dot(n, glm::normalize(below + above)) > Real(0.5));
    CHECK(blinn_phong_highlight(Color(1), 2, Color(1), n, below, above) == Color(0));
    CHECK(blinn_phong_highlight(Color(0.5f), 30, Color(2), n, below, above) == Color(0));
    // max(0, .) before the power: the light in front, the eye behind the surface with h tipped
    // away from n (n . h = -0.88): an even exponent would turn it into a highlight.
    const Vec3 front = glm::normalize(Vec3(1, 0, Real(0.2))), behind = glm::normalize(Vec3(-1, 0, -1));
    CHECK(glm::dot(n, glm::normalize(front + behind)) < 0);
    CHECK(blinn_phong_highlight(Color(1), 2, Color(1), n, front, behind) == Color(0));
    CHECK(blinn_phong_highlight(Color(1), 4, Color(1), n, front, behind) == Color(0));
}

TEST_CASE("analytic: a Lambertian sphere under one directional light, orthographic") {
    // lambert.json: unit sphere at the origin, eye on +z, window 3 high; c_r = (0.8, 0.6, 0.4),
    // c_a = 0.1, light (1,1,1) travelling along (-1,-1,-1). A pixel centre at window point
    // (x, y) sees n = (x, y, sqrt(1 - x^2 - y^2)): value = c_r c_a + c_r max(0, n . l).
    const Scene scene = load_scene_file(kScenes + "lambert.json");
    RenderOptions o;
    o.width = 120;
    o.height = 120;
    const Image img = render(scene, o).image;
    const Vec3 l = glm::normalize(Vec3(1, 1, 1));
    const Color cr(0.8f, 0.6f, 0.4f);
    int checked = 0, covered = 0, failures = 0;
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 120; ++x) {
            const double wx = -1.5 + 3.0 * (x + 0.5) / 120, wy = 1.5 - 3.0 * (y + 0.5) / 120;
            const double r2 = wx * wx + wy * wy;
            covered += img.at(x, y) != Color(0);
            if (r2 > 0.98) continue;  // leave the silhouette to the area check
            const Vec3 n(Real(wx), Real(wy), Real(std::sqrt(1 - r2)));
            const float lit = float(std::max(0.0, double(glm::dot(n, l))));
            CAPTURE(x);
            CAPTURE(y);
            CAPTURE(img.at(x, y));
            for (int c = 0; c < 3; ++c)
                RT_CHECK_FIRST(failures, img.at(x, y)[c] == doctest::Approx(cr[c] * 0.1f + cr[c] * lit).epsilon(1e-4));
            ++checked;
        }
    CHECK(checked > 4500);
    CHECK(failures == 0);
    // The silhouette: pi R^2 in pixels, to within the pixels its boundary crosses.
    const double area = M_PI / std::pow(3.0 / 120, 2), perimeter = 2 * M_PI / (3.0 / 120);
    MESSAGE("covered " << covered << " pixels, disk " << area << ", perimeter " << perimeter);
    CHECK(std::abs(covered - area) < perimeter);
}

TEST_CASE("skipping: a black light and unused materials are dropped and cost nothing") {
    SceneSummary full, lean;
    const Scene with = load_scene_file(kScenes + "skipping.json", &full);
    const Scene without = load_scene_file(kScenes + "spheres.json", &lean);
    CHECK(full.lights_black == 1);
    CHECK(full.materials_unused == 2);
    CHECK(full.lights == lean.lights);
    CHECK(with.lights.size() == 2);
    RenderOptions o;
    o.width = 64;
    o.height = 48;
    const RenderResult a = render(with, o), b = render(without, o);
    CHECK(a.counters.light_terms == b.counters.light_terms);
    CHECK(a.counters.specular_terms == b.counters.specular_terms);
    CHECK(a.counters.specular_terms < a.counters.light_terms);  // matte surfaces skip the highlight
    CHECK(a.image.pixels == b.image.pixels);
}
}  // TEST_SUITE("ch05")
