// Chapter 07: specular reflection (course §9.6): the mirror direction, the mirror series
// k^n between parallel mirrors, convergence with depth, rays counted by kind, the ray tree.
#include "app/ray_tree_svg.hpp"
#include "io/scene_file.hpp"
#include "render/integrators.hpp"
#include "render/render.hpp"
#include "shading/optics.hpp"
#include "support.hpp"
#include "support/source_dir.hpp"

#include <pcg_random.hpp>

#include <cmath>
#include <random>

using namespace rt;

namespace {

const std::string kScenes = rt::test::source_dir() + "/chapters/ch07_specular_reflection/scenes/";

// Two parallel mirrors x = -1 and x = 1 that end at z = -zmax, reflectance k, black
// otherwise; no lights, no ambient; behind them a background of 1.
Scene parallel_mirrors(float k, Real zmax, int depth) {
    Scene s = look_at(Vec3(0, 0, 1), Vec3(0), 40, make_integrator(Shading::whitted));
    s.background = Color(1);
    s.max_depth = depth;
    Material mirror{Color(0)};
    mirror.mirror = Color(k);
    const MaterialId m = s.add_material(mirror);
    for (Real x : {Real(-1), Real(1)})
        s.surfaces.add(Polygon({Vec3(x, -5, 1), Vec3(x, 5, 1), Vec3(x, 5, -zmax), Vec3(x, -5, -zmax)}), m);
    return s;
}

Color trace(const Scene& scene, const Ray& ray, RayCounters& counters, RayTree* tree = nullptr) {
    Sampler sampler(0, 0);
    TraceContext context{sampler, counters};
    context.tree = tree;
    return scene.integrator->Li(scene, ray, context);
}

}  // namespace

TEST_SUITE("ch07") {
TEST_CASE("7.1 reflect: r = d - 2 (d . n) n, with the course's signs") {
    CHECK(reflect(Vec3(1, -1, 0), Vec3(0, 1, 0)) == Vec3(1, 1, 0));
    CHECK(reflect(Vec3(1, -1, 0), Vec3(0, -1, 0)) == Vec3(1, 1, 0));  // either side of the surface
    CHECK(reflect(Vec3(0, 0, -2), Vec3(0, 0, 1)) == Vec3(0, 0, 2));   // straight back, length kept
    pcg32 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    int failures = 0;
    for (int k = 0; k < 1000; ++k) {
        const Vec3 d{Real(u(rng)), Real(u(rng)), Real(u(rng))};
        const Vec3 n = unit_vector(Vec3{Real(u(rng)), Real(u(rng)), Real(u(rng))});
        const Vec3 r = reflect(d, n);
        // The angle of incidence equals the angle of reflection, the tangent part is kept,
        // and reflecting twice gives d back.
        RT_CHECK_FIRST(failures, std::abs(glm::dot(r, n) + glm::dot(d, n)) <= 8 * test::kEps);
        RT_CHECK_FIRST(failures, glm::length(r - d + 2 * glm::dot(d, n) * n) <= 8 * test::kEps);
        RT_CHECK_FIRST(failures, glm::length(reflect(r, n) - d) <= 16 * test::kEps);
    }
    CHECK(failures == 0);
}

TEST_CASE("analytic: between parallel mirrors of reflectance k the n-th image carries k^n") {
    // A ray from the origin along (1, 0, -c) meets the mirrors at z = -c, -3c, -5c, ...:
    // n = floor((zmax/c - 1)/2) + 1 reflections before it passes their end and sees the
    // background. Each reflection multiplies by k; past the depth limit it sees black.
    const float k = 0.8f;
    const Real zmax = 10;
    for (int depth : {3, 8}) {
        const Scene scene = parallel_mirrors(k, zmax, depth);
        for (int n = 1; n <= 6; ++n) {
            const Real c = zmax / Real(2 * n - 1) * Real(0.999);  // the n-th hit just inside the end
            CAPTURE(depth);
            CAPTURE(n);
            RayCounters counters;
            const Color got = trace(scene, Ray{Vec3(0), Vec3(1, 0, -c)}, counters);
            const float want = n <= depth ? std::pow(k, float(n)) : 0.0f;
            CHECK(got.r == doctest::Approx(want).epsilon(1e-6));
            CHECK(counters.of(RayKind::reflection) == std::uint64_t(std::min(n, depth)));
        }
    }
}

TEST_CASE("7.1 the mirrors scene converges as depth grows: each step changes it by less than 0.85^depth") {
    Scene scene = load_scene_file(kScenes + "mirrors.json");
    RenderOptions o;
    o.width = 80;
    o.height = 60;
    scene.max_depth = 0;
    Image previous = render(scene, o).image;
    for (int depth = 1; depth <= 8; ++depth) {
        scene.max_depth = depth;
        const Image img = render(scene, o).image;
        float change = 0;
        for (std::size_t p = 0; p < img.pixels.size(); ++p)
            for (int c = 0; c < 3; ++c) change = std::max(change, std::abs(img.pixels[p][c] - previous.pixels[p][c]));
        // A ray's colour is below 1.6 in this scene; what depth d adds went through d
        // mirrors of 0.85.
        CAPTURE(depth);
        CHECK(change > 0);
        CHECK(change <= 1.6f * std::pow(0.85f, float(depth)));
        previous = img;
    }
}

TEST_CASE("7.1 no reflection ray for a black mirror colour; rays counted by kind") {
    Scene scene = load_scene_file(kScenes + "tinted-sphere.json");
    RenderOptions o;
    o.width = 40;
    o.height = 30;
    const RayCounters with = render(scene, o).counters;
    CHECK(with.of(RayKind::camera) == 1200);
    CHECK(with.of(RayKind::reflection) > 100);  // the gold sphere's pixels
    CHECK(with.of(RayKind::refraction) == 0);
    CHECK(with.total() == with.of(RayKind::camera) + with.of(RayKind::shadow) + with.of(RayKind::reflection));
    for (Material& m : scene.materials) m.mirror = Color(0);
    CHECK(render(scene, o).counters.of(RayKind::reflection) == 0);
}

TEST_CASE("7.1 the ray tree of a mirror pixel: camera ray, its shadow rays, the reflection and its own") {
    const Scene scene = parallel_mirrors(0.5f, 10, 8);
    RayCounters counters;
    RayTree tree;
    const Color c = trace(scene, Ray{Vec3(0), Vec3(1, 0, Real(-2.5))}, counters, &tree);
    // Hits at z = -2.5 and -7.5, then past the end at -10: two reflections, 0.5^2.
    CHECK(c.r == doctest::Approx(0.25));
    REQUIRE(tree.nodes.size() == 3);
    CHECK(tree.nodes[0].kind == RayKind::camera);
    CHECK(tree.nodes[0].parent == -1);
    CHECK(tree.nodes[0].hit);
    CHECK(tree.nodes[0].record.t == doctest::Approx(1));
    CHECK(tree.nodes[1].kind == RayKind::reflection);
    CHECK(tree.nodes[1].parent == 0);
    CHECK(std::string(tree.nodes[1].weight_of) == "mirror colour");
    CHECK(tree.nodes[1].weight.r == doctest::Approx(0.5));
    CHECK(tree.nodes[1].radiance.r == doctest::Approx(0.5));  // what came back: 0.5 x background
    CHECK(tree.nodes[2].parent == 1);
    CHECK_FALSE(tree.nodes[2].hit);
    CHECK(tree.nodes[2].radiance == Color(1));
    CHECK(tree.nodes[2].depth == 2);
}
}

TEST_CASE("7.1 the ray tree draws as SVG: one line per ray, the blocked shadow rays in red") {
    Scene scene = parallel_mirrors(0.5f, 10, 8);
    Light light;
    light.position = Vec3(0, 3, -3);
    scene.lights.push_back(light);
    scene.materials[1].diffuse = Color(0.3f);  // so that the mirrors cast shadow rays
    RayCounters counters;
    RayTree tree;
    const Color c = trace(scene, Ray{Vec3(0), Vec3(1, 0, Real(-2.5))}, counters, &tree);
    const std::string svg = ray_tree_svg(scene, tree, "two mirrors", c);
    CHECK(svg.rfind("<svg", 0) == 0);
    std::size_t lines = 0;
    for (std::size_t at = svg.find("<line"); at != std::string::npos; at = svg.find("<line", at + 1)) ++lines;
    CHECK(lines == tree.nodes.size());
    CHECK(tree.nodes.size() == 5);  // camera, 2 reflections, a shadow ray from each mirror hit
    CHECK(svg.find("two mirrors") != std::string::npos);
    CHECK(svg.find("mirror colour") != std::string::npos);
}
