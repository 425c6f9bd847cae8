// Reading files that may be bad: the JSON scanner and its locations, OBJ meshes, images,
// and every input a fuzzer ever broke a reader with.
#include "core/limits.hpp"
#include "io/image_file.hpp"
#include "io/json_locations.hpp"
#include "io/obj.hpp"
#include "io/scene_file.hpp"
#include "support.hpp"
#include "support/source_dir.hpp"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

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
