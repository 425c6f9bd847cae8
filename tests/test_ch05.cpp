// Chapter 05: the ray tracing program (§9.4-9.4.1): closest hit, shading, scene files.
#include "common/integrators.hpp"
#include "common/obj.hpp"
#include "common/render.hpp"
#include "common/scene_file.hpp"
#include "common/sphere.hpp"
#include "common/surface_list.hpp"
#include "support.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <unistd.h>

using namespace rt;
namespace fs = std::filesystem;

namespace {

const std::string kScenes = std::string(RTLAB_SOURCE_DIR) + "/chapters/ch05_ray_tracing_program/scenes/";

std::string load_error(const std::string& text) {
    try {
        load_scene_text(text, "test.json", ".");
    } catch (const SceneError& e) {
        return e.what();
    }
    return "no error";
}

const char* kMinimal = R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0]}, "surfaces": []})";

}  // namespace

TEST_SUITE("ch05") {

TEST_CASE("5.1 SurfaceList::hit returns the closest hit in [t0, t1], whatever the order") {
    auto near = std::make_shared<Sphere>("near", Vec3(0, 0, -3), 1);
    auto far = std::make_shared<Sphere>("far", Vec3(0, 0, -10), 2);
    for (bool near_first : {true, false}) {
        SurfaceList list;
        list.add(near_first ? near : far);
        list.add(near_first ? far : near);
        HitRecord rec;
        const Ray r{Vec3(0), Vec3(0, 0, -1)};
        REQUIRE(list.hit(r, 0, kInfinity, rec));
        CHECK(rec.surface == near.get());
        CHECK(rec.t == doctest::Approx(2));
        REQUIRE(list.hit(r, 4.5, kInfinity, rec));  // past the near sphere
        CHECK(rec.surface == far.get());
        CHECK(rec.t == doctest::Approx(8));
        CHECK_FALSE(list.hit(r, 0, 1.5, rec));
        CHECK(list.bounding_box().min.z == doctest::Approx(-12));
    }
    HitRecord rec;
    CHECK_FALSE(SurfaceList().hit(Ray{Vec3(0), Vec3(1, 0, 0)}, 0, kInfinity, rec));
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
    int checked = 0, covered = 0;
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 120; ++x) {
            const double wx = -1.5 + 3.0 * (x + 0.5) / 120, wy = 1.5 - 3.0 * (y + 0.5) / 120;
            const double r2 = wx * wx + wy * wy;
            covered += img.at(x, y) != Color(0);
            if (r2 > 0.98) continue;  // leave the silhouette to the area check
            const Vec3 n(Real(wx), Real(wy), Real(std::sqrt(1 - r2)));
            const float lit = float(std::max(0.0, double(glm::dot(n, l))));
            for (int c = 0; c < 3; ++c) CHECK(img.at(x, y)[c] == doctest::Approx(cr[c] * 0.1f + cr[c] * lit).epsilon(1e-4));
            ++checked;
        }
    CHECK(checked > 4500);
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

TEST_CASE("every shipped scene file loads") {
    int n = 0;
    for (const auto& e : fs::directory_iterator(kScenes)) {
        CAPTURE(e.path().string());
        SceneSummary s;
        const Scene scene = load_scene_file(e.path().string(), &s);
        CHECK(scene.world != nullptr);
        CHECK(s.surfaces > 0);
        ++n;
    }
    CHECK(n >= 4);
}

TEST_CASE("scene file errors name the file, line, column and key") {
    CHECK(load_error(kMinimal) == "no error");
    CHECK(load_error("{\n  \"camera\": {\"eye\": [0, 0, 5], \"target\": [0, 0, 0]},\n  \"surfaces\": [],\n  \"colour\": 1\n}") ==
          "test.json:4:3: /colour: unknown key 'colour' (expected one of: $schema, description, camera, shading, "
          "background, ambient, materials, lights, surfaces)");
    CHECK(load_error("{\"camera\": {\"eye\": [0, 0, 5], \"target\": [0, 0, 0]},\n \"surfaces\": [\n  {\"type\": \"sphere\", "
                     "\"center\": [0, 0, 0], \"radius\": -1}]}") ==
          "test.json:3:43: /surfaces/0/radius: must be > 0");
    CHECK(load_error("{\"camera\": {\"eye\": [0, 0, 5], \"target\": [0, 0, 0]},\n \"surfaces\": [\n  {\"type\": \"sphere\", "
                     "\"center\": [0, 0], \"radius\": 1}]}") ==
          "test.json:3:22: /surfaces/0/center: must be an array of 3 numbers");
    CHECK(load_error("{\"camera\": {\"eye\": [0, 0, 5]\n, \"target\": [0, 0, 0]},,}") .find("test.json:2:24: not valid JSON") == 0);
    CHECK(load_error(R"({"surfaces": []})") == "test.json:1:1: /: missing key 'camera'");
    CHECK(load_error(R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 5]}, "surfaces": []})") ==
          "test.json:1:2: /camera: camera: eye and target are the same point");
    const std::string prefix = R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0]}, )";
    CHECK(load_error(prefix + R"("surfaces": [{"type": "sphere", "center": [0,0,0], "radius": 1, "material": "gold"}]})")
              .find("/surfaces/0/material: no material named \"gold\"") != std::string::npos);
    CHECK(load_error(prefix + R"("surfaces": [{"type": "teapot"}]})").find("unknown surface type \"teapot\"") != std::string::npos);
    CHECK(load_error(prefix + R"("surfaces": [{"type": "polygon", "vertices": [[0,0,0],[1,1,1],[2,2,2]]}]})")
              .find("/surfaces/0: polygon 'polygon 0': has no area") != std::string::npos);
    CHECK(load_error(prefix + R"("surfaces": [{"type": "mesh", "file": "no/such.obj"}]})")
              .find("/surfaces/0/file: mesh ./no/such.obj: no such file") != std::string::npos);
    CHECK(load_error(prefix + R"("lights": [{"type": "spot", "position": [0,0,0]}], "surfaces": []})")
              .find("/lights/0/type: must be \"point\" or \"directional\"") != std::string::npos);
    CHECK(load_error(prefix + R"("materials": {"m": {"diffuse": [1,1,1], "shine": 3}}, "surfaces": []})")
              .find("/materials/m/shine: unknown key 'shine'") != std::string::npos);
    CHECK(load_error(prefix + R"("shading": "toon", "surfaces": []})").find("unknown shading \"toon\"") != std::string::npos);
    CHECK_THROWS_WITH_AS(load_scene_file("/no/such/scene.json"), "/no/such/scene.json: cannot open scene file", SceneError);
}

TEST_CASE("OBJ meshes: faces fanned into triangles, bad files rejected in one line") {
    const fs::path dir = fs::temp_directory_path() / ("rtlab-obj-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "quad.obj") << "# a unit square as one quad and a triangle\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\n"
                                       "f 1 2 3 4\nf 2 5 3\n";
    const MeshData m = load_obj((dir / "quad.obj").string());
    CHECK(m.positions.size() == 5);
    CHECK(m.triangles.size() == 3);
    std::ofstream(dir / "bad.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n";
    CHECK_THROWS_AS(load_obj((dir / "bad.obj").string()), std::runtime_error);
    std::ofstream(dir / "empty.obj") << "# nothing\n";
    CHECK_THROWS_WITH_AS(load_obj((dir / "empty.obj").string()), doctest::Contains("no triangles"), std::runtime_error);
    std::ofstream(dir / "binary.obj") << std::string("\x00\x01\x02\xff garbage", 12);
    CHECK_THROWS_AS(load_obj((dir / "binary.obj").string()), std::runtime_error);
    // From a scene file, relative to it, with scale and translate.
    std::ofstream(dir / "scene.json") << R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0]},
        "surfaces": [{"type": "mesh", "file": "quad.obj", "scale": 2, "translate": [0, 0, -1]}]})";
    SceneSummary s;
    const Scene scene = load_scene_file((dir / "scene.json").string(), &s);
    CHECK(s.triangles == 3);
    HitRecord rec;
    REQUIRE(scene.hit(Ray{Vec3(0.5, 0.5, 5), Vec3(0, 0, -1)}, 0, kInfinity, rec));
    CHECK(rec.t == doctest::Approx(6));
    fs::remove_all(dir);
}

}
