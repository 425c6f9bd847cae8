// Bad input and numbers at the edge of their ranges: the JSON scanner, the limits table,
// messages on one line, the OBJ and image readers, and finite results by construction.
#include "core/text.hpp"
#include "geometry/limits.hpp"
#include "io/image_file.hpp"
#include "io/json_locations.hpp"
#include "io/obj.hpp"
#include "io/scene_file.hpp"
#include "render/integrators.hpp"
#include "render/render.hpp"
#include "support.hpp"
#include "support/source_dir.hpp"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

using namespace rt;

TEST_SUITE("common") {
TEST_CASE("locate: the line and column of a value by JSON pointer, for members at their key") {
    const std::string text = "{\n  \"a\": [1, {\"b~/c\": 2}],\n  \"k\\u00e9y\": \"v\"\n}";
    const auto a = locate(text, "/a");
    REQUIRE(a);
    CHECK(a->line == 2);
    CHECK(a->column == 3);
    const auto element = locate(text, "/a/1");
    REQUIRE(element);
    CHECK(element->column == 12);
    const auto escaped = locate(text, "/a/1/b~0~1c");  // RFC 6901: ~0 is ~, ~1 is /
    REQUIRE(escaped);
    CHECK(escaped->column == 13);
    const auto unicode = locate(text, "/k\xc3\xa9y");  // \u00e9 decoded, as the parser decodes it
    REQUIRE(unicode);
    CHECK(unicode->line == 3);
    CHECK_FALSE(locate(text, "/a/2"));
    CHECK_FALSE(locate(text, "/nope"));
    CHECK(locate(text, "")->line == 1);
}

TEST_CASE("locate and check_json_text end on any bytes, and on nesting far past any stack") {
    const std::string deep(1000000, '[');
    CHECK_FALSE(locate(deep, "/0/0/0/1"));
    const auto problem = check_json_text(deep);
    REQUIRE(problem);
    CHECK(problem->message == "JSON nesting depth must be in 1..32, not 33");
    CHECK(problem->offset == 32);
    for (const char* junk : {"", "]", "}}}", "{\"a\"", "{\"a\":", "[1 2 3", "\"unterminated", "{,}", "\\u12"}) {
        CAPTURE(junk);
        CHECK_FALSE(check_json_text(junk));
        CHECK_FALSE(locate(junk, "/a"));
    }
    // 32 levels are allowed, 33 are not.
    CHECK_FALSE(check_json_text(std::string(32, '[') + std::string(32, ']')));
    CHECK(check_json_text(std::string(33, '[') + std::string(33, ']')));
}

TEST_CASE("check_json_text: a number too large for a double is named with its pointer") {
    const auto problem = check_json_text(R"({"s": [{"r": 1e400}], "t": -1e-400})");
    REQUIRE(problem);
    CHECK(problem->pointer == "/s/0/r");
    CHECK(problem->message == "number 1e400 is too large to hold");
    CHECK_FALSE(check_json_text(R"({"r": 1.7976931348623157e308, "tiny": 1e-400})"));
    CHECK(check_json_text(R"([-1.8e308])"));
}

TEST_CASE("limits: one table, messages that name the limit, numbers written as people write them") {
    CHECK(limits::refuse(limits::icosphere_subdivisions, 9) == "icosphere subdivisions must be in 0..7, not 9");
    CHECK(limits::refuse(limits::length, -1) == "length must be in 1e-6..1e8, not -1");
    CHECK(limits::refuse(limits::radiance, 1e39) == "radiance must be in 0..1000000, not 1e39");
    CHECK(limits::refuse(limits::field_of_view, 180) == "field of view must be in 0.001..179.9 degrees, not 180");
    CHECK(limits::describe(limits::triangle_vertices) == "must be 3");
    CHECK_FALSE(limits::contains(limits::coordinate, std::nan("")));
    for (const auto& r : limits::all) {
        CAPTURE(r.name);
        CHECK(r.min <= r.max);
        // Every value a scene may hold stays finite and, where it must be positive, non-zero
        // as a float: colours are float whatever Real is.
        if (*r.schema) {
            CHECK(std::isfinite(float(r.max)));
            CHECK(std::isfinite(float(r.min)));
            if (r.min > 0) CHECK(float(r.min) > 0);
        }
    }
    // The products the ray tests form stay far from float's range: (2 * max)^3.
    CHECK(std::pow(2 * limits::coordinate.max, 3) < 1e-10 * std::numeric_limits<float>::max());
}

TEST_CASE("one_line: control characters become escapes, UTF-8 stays") {
    CHECK(one_line("a\nb\tc\x1b[31m") == "a\\nb\\tc\\x1b[31m");
    CHECK(one_line("caf\xc3\xa9") == "caf\xc3\xa9");
    CHECK(one_line(std::string("\0x", 2)) == "\\x00x");
}

TEST_CASE("unit_vector: any finite non-zero vector, huge or tiny, in float as in double") {
    const Real big = std::numeric_limits<Real>::max() / 4, tiny = std::numeric_limits<Real>::denorm_min() * 8;
    for (const Vec3& v :
         {Vec3(0, -big, 0), Vec3(big, big, big), Vec3(0, tiny, 0), Vec3(tiny, -tiny, 0), Vec3(3, 4, 0)}) {
        CAPTURE(v);
        const Vec3 u = unit_vector(v);
        CHECK(std::abs(glm::length(u) - 1) < 4 * std::numeric_limits<Real>::epsilon());
        CHECK(glm::dot(u, v) > 0);
    }
    CHECK(unit_vector(Vec3(3, 4, 0)) == Vec3(Real(0.6), Real(0.8), 0));
    CHECK(unit_vector(Vec3(0)) == Vec3(0));
}

TEST_CASE("a light at the shading point, or far away and tiny, gives finite light") {
    Light point;
    point.position = Vec3(1, 2, 3);
    const LightSample at = point.sample(Vec3(1, 2, 3));
    CHECK(at.color == Color(0));
    CHECK(std::isfinite(at.direction.x + at.direction.y + at.direction.z));
    Light sun;
    sun.type = Light::Type::directional;
    sun.direction = Vec3(0, Real(-1e-30), 0);  // its square underflows in float (and 1e-200 in double)
    CHECK(sun.sample(Vec3(0)).direction == Vec3(0, 1, 0));
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

TEST_CASE("OBJ: line numbers in messages, faces fanned from their first corner") {
    const MeshData quad = load_obj_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n", "q.obj");
    REQUIRE(quad.triangles.size() == 2);
    CHECK(quad.triangles[0] == std::array<std::uint32_t, 3>{0, 1, 2});
    CHECK(quad.triangles[1] == std::array<std::uint32_t, 3>{0, 2, 3});
    const MeshData relative = load_obj_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n", "r.obj");
    CHECK(relative.triangles.at(0) == std::array<std::uint32_t, 3>{0, 1, 2});
    CHECK_THROWS_WITH_AS(load_obj_text("v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 99999999999\n", "big.obj"),
                         "mesh big.obj:5: vertex index 99999999999, but the file has 3 vertices", std::runtime_error);
    CHECK_THROWS_WITH_AS(load_obj_text("v 0 0 0\nf 1 1\n", "two.obj"),
                         "mesh two.obj:2: OBJ face corners must be in 3..255, not 2", std::runtime_error);
    CHECK_THROWS_WITH_AS(load_obj_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "zero.obj"),
                         "mesh zero.obj:4: vertex index 0 (OBJ counts vertices from 1)", std::runtime_error);
    // Coordinates that are not finite numbers, which tinyobjloader would read as 0; numbers
    // as OBJ files write them load.
    for (const char* bad : {"nan", "-inf", "inf", "abc", "1e400", "+", ".", "1e+", "1,5", "0x10"})
        CHECK_THROWS_WITH_AS(
            load_obj_text(std::string("v 0 0 0\nv 1 0 0\n\nv 0 ") + bad + " 0\nf 1 2 3\n", "bad.obj"),
            ("mesh bad.obj:4: vertex coordinate '" + std::string(bad) + "' is not a finite number").c_str(),
            std::runtime_error);
    CHECK_THROWS_WITH_AS(load_obj_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 nan 1\nf 1//1 2//1 3//1\n", "n.obj"),
                         "mesh n.obj:4: vertex normal coordinate 'nan' is not a finite number", std::runtime_error);
    CHECK_THROWS_WITH_AS(load_obj_text("v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n", "two.obj"),
                         "mesh two.obj:2: vertex has 2 coordinates, not 3", std::runtime_error);
    const MeshData forms =
        load_obj_text("v -0 +0 0.\nv 1.5e0 .0 -0e-3\nv 0 1E+0 0 1\nvn 0 0 1\nf 1//1 2//1 3//1\n", "f.obj");
    CHECK(forms.positions.at(1) == Vec3(Real(1.5), 0, 0));
    CHECK(forms.positions.at(2) == Vec3(0, 1, 0));
    // A polygon of 255 corners (tinyobjloader's limit): 253 triangles; one more corner is
    // refused, not wrapped round to 0.
    std::string ring, face = "f";
    const int n = 255;
    for (int k = 0; k < n; ++k) {
        // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) about
        // " " + std::to_string(...).
        ring += "v ";
        ring += std::to_string(std::cos(2 * M_PI * k / n));
        ring += ' ';
        ring += std::to_string(std::sin(2 * M_PI * k / n));
        ring += " 0\n";
        face += ' ';
        face += std::to_string(k + 1);
    }
    CHECK(load_obj_text(ring + face + "\n", "ring.obj").triangles.size() == std::size_t(n - 2));
    CHECK_THROWS_WITH_AS(load_obj_text(ring + "v 0 0 1\n" + face + " 256\n", "ring.obj"),
                         "mesh ring.obj:257: OBJ face corners must be in 3..255, not 256", std::runtime_error);
}

TEST_CASE("images: sizes checked before decoding, PFM pixels finite and exactly as many as the header says") {
    const std::string header = "PF\n2 1\n-1.0\n";
    std::string pixels(24, '\0');
    const float values[6] = {0.25f, 0.5f, 1, 0, 2, 4};
    std::memcpy(pixels.data(), values, sizeof values);
    const Image image = decode_pfm(header + pixels, "ok.pfm");
    CHECK(image.width == 2);
    CHECK(image.at(1, 0) == Color(0, 2, 4));
    CHECK_THROWS_WITH_AS(decode_pfm(header + pixels + "x", "long.pfm"),
                         "cannot read image long.pfm: holds 25 bytes of pixels, not 24 for 2x1", std::runtime_error);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(pixels.data() + 4, &nan, 4);
    CHECK_THROWS_WITH_AS(decode_pfm(header + pixels, "nan.pfm"), "cannot read image nan.pfm: pixel 0,0 is not finite",
                         std::runtime_error);
    CHECK_THROWS_WITH_AS(decode_pfm("PF\n16385 1\n-1.0\n", "wide.pfm"),
                         "cannot read image wide.pfm: image width and height must be in 1..16384 pixels, not 16385",
                         std::runtime_error);
    CHECK_THROWS_WITH_AS(decode_image("GIF89a", "x.gif"), "cannot read image x.gif: not a PNG file",
                         std::runtime_error);
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
}  // TEST_SUITE("common")

TEST_SUITE("common") {
TEST_CASE("fuzz regressions: every input a fuzzer ever broke a reader with now gets one line of error or a result") {
    namespace fs = std::filesystem;
    const fs::path root = fs::path(rt::test::source_dir()) / "tests/fuzz/regressions";
    int replayed = 0;
    for (const char* target : {"scene", "json", "obj", "image"}) {
        if (!fs::is_directory(root / target)) continue;
        for (const auto& entry : fs::directory_iterator(root / target)) {
            std::ifstream in(entry.path(), std::ios::binary);
            const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            CAPTURE(entry.path().string());
            std::string message;
            try {
                if (std::string(target) == "scene") (void)load_scene_text(bytes, "fuzz.json", "/nonexistent");
                if (std::string(target) == "json") (void)check_json_text(bytes);
                if (std::string(target) == "obj") (void)load_obj_text(bytes, "fuzz.obj");
                if (std::string(target) == "image") (void)decode_image(bytes, "fuzz");
            } catch (const std::runtime_error& e) {
                message = e.what();
            }
            CHECK(message.find('\n') == std::string::npos);
            ++replayed;
        }
    }
    CHECK(replayed >= 1);
}
}  // TEST_SUITE("common")
