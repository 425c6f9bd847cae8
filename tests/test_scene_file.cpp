// The scene-file loader and OBJ reader of the common library (book chapter 05, appendix A).
#include "io/obj.hpp"
#include "io/scene_file.hpp"
#include "support.hpp"
#include "support/source_dir.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include <unistd.h>
#include <filesystem>
#include <fstream>

using namespace rt;
namespace fs = std::filesystem;

namespace {

const std::string kScenes = rt::test::source_dir() + "/chapters/ch05_ray_tracing_program/scenes/";

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

TEST_SUITE("common") {
TEST_CASE("every shipped scene file loads") {
    int n = 0;
    for (const auto& e : fs::directory_iterator(kScenes)) {
        CAPTURE(e.path().string());
        SceneSummary s;
        const Scene scene = load_scene_file(e.path().string(), &s);
        CHECK_FALSE(scene.surfaces.empty());
        CHECK(s.surfaces > 0);
        ++n;
    }
    CHECK(n >= 4);
}

TEST_CASE("scene file errors name the file, line, column and key") {
    CHECK(load_error(kMinimal) == "no error");
    CHECK(load_error("{\n  \"camera\": {\"eye\": [0, 0, 5], \"target\": [0, 0, 0]},\n  \"surfaces\": [],\n  "
                     "\"colour\": 1\n}") ==
          "test.json:4:3: /colour: unknown key 'colour' (expected one of: $schema, accel, ambient, antialiasing, "
          "background, camera, description, lights, materials, max_depth, offset, shading, shapes, surfaces)");
    CHECK(load_error(
              "{\"camera\": {\"eye\": [0, 0, 5], \"target\": [0, 0, 0]},\n \"surfaces\": [\n  {\"type\": \"sphere\", "
              "\"center\": [0, 0, 0], \"radius\": -1}]}") ==
          "test.json:3:43: /surfaces/0/radius: length must be in 1e-6..1e8, not -1");
    CHECK(load_error(
              "{\"camera\": {\"eye\": [0, 0, 5], \"target\": [0, 0, 0]},\n \"surfaces\": [\n  {\"type\": \"sphere\", "
              "\"center\": [0, 0], \"radius\": 1}]}") ==
          "test.json:3:22: /surfaces/0/center: must be an array of 3 numbers");
    CHECK(load_error("{\"camera\": {\"eye\": [0, 0, 5]\n, \"target\": [0, 0, 0]},,}")
              .find("test.json:2:24: not valid JSON") == 0);
    CHECK(load_error(R"({"surfaces": []})") == "test.json:1:1: /: missing key 'camera'");
    CHECK(load_error(R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 5]}, "surfaces": []})") ==
          "test.json:1:2: /camera: camera: eye and target are the same point");
    const std::string prefix = R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0]}, )";
    CHECK(
        load_error(prefix + R"("surfaces": [{"type": "sphere", "center": [0,0,0], "radius": 1, "material": "gold"}]})")
            .find("/surfaces/0/material: no material named \"gold\"") != std::string::npos);
    CHECK(load_error(prefix + R"("surfaces": [{"type": "teapot"}]})").find("unknown surface type \"teapot\"") !=
          std::string::npos);
    CHECK(load_error(prefix + R"("surfaces": [{"type": "polygon", "vertices": [[0,0,0],[1,1,1],[2,2,2]]}]})")
              .find("/surfaces/0: polygon: has no area") != std::string::npos);
    CHECK(load_error(prefix + R"("surfaces": [{"type": "mesh", "file": "no/such.obj"}]})")
              .find("/surfaces/0/file: mesh ./no/such.obj: no such file") != std::string::npos);
    CHECK(load_error(prefix + R"("lights": [{"type": "spot", "position": [0,0,0]}], "surfaces": []})")
              .find("/lights/0/type: unknown light type \"spot\" (expected point, directional or parallelogram)") !=
          std::string::npos);
    CHECK(load_error(prefix + R"("materials": {"m": {"diffuse": [1,1,1], "shine": 3}}, "surfaces": []})")
              .find("/materials/m/shine: unknown key 'shine'") != std::string::npos);
    CHECK(load_error(prefix + R"("shading": "toon", "surfaces": []})").find("unknown shading \"toon\"") !=
          std::string::npos);
    CHECK_THROWS_WITH_AS(load_scene_file("/no/such/scene.json"), "scene file /no/such/scene.json: no such file",
                         SceneError);
}

TEST_CASE("OBJ meshes: faces fanned into triangles, bad files rejected in one line") {
    const fs::path dir = fs::temp_directory_path() / ("rtlab-obj-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "quad.obj")
        << "# a unit square as one quad and a triangle\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\n"
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
    REQUIRE(scene.hit(Ray{Vec3(0.5, 0.5, 5), Vec3(0, 0, -1)}, Interval{}, rec));
    CHECK(rec.t == doctest::Approx(6));
    fs::remove_all(dir);
}

TEST_CASE("a confined scene names files only under its folders, refused in one line before they are opened") {
    const fs::path dir = fs::temp_directory_path() / ("rtlab-access-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    for (const char* d : {"scenes/sub", "scenes-too", "outside"}) fs::create_directories(dir / d);
    const char* triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    std::ofstream(dir / "scenes/tri.obj") << triangle;
    std::ofstream(dir / "scenes-too/tri.obj") << triangle;  // its folder's name starts like the allowed one
    std::ofstream(dir / "outside/secret.obj") << "v zz_secret_token 0 0\n";
    fs::create_symlink("../outside", dir / "scenes/out");         // a link that leads out
    fs::create_symlink("../tri.obj", dir / "scenes/sub/up.obj");  // a link that stays in
    const std::string scenes = fs::canonical(dir / "scenes").string();
    const FileAccess access({scenes}, "--allow DIR adds a folder");
    const auto load = [&](const std::string& file, const FileAccess& a) -> std::string {
        const std::string text = R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0]}, "surfaces": [)"
                                 R"({"type": "mesh", "file": ")" +
                                 file + R"("}]})";
        try {
            load_scene_text(text, "posted.json", scenes, nullptr, a);
        } catch (const SceneError& e) {
            return e.what();
        }
        return "loaded";
    };
    for (const std::string& inside : std::vector<std::string>{"tri.obj", "sub/../tri.obj", "sub/up.obj",
                                                              "sub/missing/../../tri.obj", scenes + "/tri.obj"}) {
        CAPTURE(inside);
        CHECK(load(inside, access) == "loaded");
    }
    // Absolute, "..", through a link, a neighbour whose name begins the same, a file that is
    // not there: each the same line, naming the rule and not a byte of the file.
    for (const std::string& outside :
         std::vector<std::string>{(dir / "outside/secret.obj").string(), "../outside/secret.obj", "out/secret.obj",
                                  "sub/../../outside/secret.obj", "../scenes-too/tri.obj", "/etc/passwd",
                                  "../outside/missing.obj", "tri.obj/../../outside/secret.obj"}) {
        CAPTURE(outside);
        CHECK(load(outside, access) == "posted.json:1:83: /surfaces/0/file: '" + outside +
                                           "' is refused: this scene may only name files under " + scenes +
                                           " (--allow DIR adds a folder)");
    }
    // Another folder allowed; a scene file from the command line may name any file, and the
    // OBJ reader's line quotes the file, as it always has.
    CHECK(load("../outside/secret.obj", FileAccess({scenes, (dir / "outside").string()}, "")).find("zz_secret_token") !=
          std::string::npos);
    CHECK(load("../outside/secret.obj", FileAccess{}).find("zz_secret_token") != std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("the book's scene-format examples load, and the schema is valid JSON") {
    // Appendix A's ```json blocks are complete scenes: the documentation cannot drift from
    // the loader without this failing.
    std::ifstream book(rt::test::source_dir() + "/book/appendix-a-scene-format.md");
    REQUIRE(book);
    std::string line, block;
    bool inside = false;
    int examples = 0;
    while (std::getline(book, line)) {
        if (!inside && line.rfind("```json", 0) == 0) {
            inside = true;
            block.clear();
        } else if (inside && line.rfind("```", 0) == 0) {
            inside = false;
            ++examples;
            CAPTURE(block);
            CHECK_NOTHROW(load_scene_text(block, "appendix example " + std::to_string(examples), "."));
        } else if (inside) {
            block += line + "\n";
        }
    }
    CHECK(examples >= 2);
    std::ifstream schema(rt::test::source_dir() + "/common/io/scene.schema.json");
    REQUIRE(schema);
    const auto parsed = nlohmann::json::parse(schema, nullptr, false);
    CHECK_FALSE(parsed.is_discarded());
    CHECK(parsed.contains("properties"));
}
}  // TEST_SUITE("common")

TEST_SUITE("common") {
// Chapters 16 and 18: what needs none of their exercises (the stubs must fail every test of
// a chapter's own program).
TEST_CASE("scene files: a lens needs a perspective camera and an aperture") {
    CHECK_THROWS_WITH(load_scene_text(R"({"camera": {"projection": "orthographic", "eye": [0, 0, 3],
        "target": [0, 0, 0], "aperture": 0.2}, "surfaces": []})",
                                      "o.json", "."),
                      doctest::Contains("a lens (aperture > 0) needs a perspective camera"));
    CHECK_THROWS_WITH(load_scene_text(R"({"camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "lens": "disk"},
        "surfaces": []})",
                                      "l.json", "."),
                      doctest::Contains("a lens needs an aperture > 0"));
    CHECK_THROWS_WITH(load_scene_text(R"({"camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "aperture": 1,
        "lens": "hexagon"}, "surfaces": []})",
                                      "h.json", "."),
                      doctest::Contains("/camera/lens: unknown lens \"hexagon\" (expected square or disk)"));
}

TEST_CASE("scene values are range-checked as stored: colours as float, coordinates within 1e8") {
    const auto error = [](const std::string& surfaces, const std::string& extra = "") {
        try {
            load_scene_text(R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0]}, )" + extra + R"("surfaces": [)" +
                                surfaces + "]}",
                            "t.json", ".");
        } catch (const SceneError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    CHECK(error(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1e39})") ==
          "t.json:1:106: /surfaces/0/radius: length must be in 1e-6..1e8, not 1e39");
    CHECK(error("", R"("background": [1e39, 0, 0], )") ==
          "t.json:1:68: /background/0: radiance must be in 0..1000000, not 1e39");
    CHECK(error("", R"("ambient": [0, 3.5e38, 0], )") ==
          "t.json:1:68: /ambient/1: radiance must be in 0..1000000, not 3.5e38");
    CHECK(error(R"({"type": "sphere", "center": [0, 0, 1e8], "radius": 1e8})") == "no error");
    // A mesh's vertices are checked after scale and translate.
    CHECK(error(R"({"type": "soup", "center": [1e8, 0, 0], "size": 1e8, "scale": 1, "count": 3})")
              .find("coordinate must be in -1e8..1e8") != std::string::npos);
}
}  // TEST_SUITE("common")
