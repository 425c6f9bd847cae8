// Geometry the exercises build on but do not implement: meshes and polygon validation.
#include "geometry/mesh.hpp"
#include "geometry/polygon.hpp"
#include "geometry/procedural.hpp"
#include "geometry/triangle.hpp"
#include "support.hpp"

#include <cmath>
#include <map>

using namespace rt;

TEST_SUITE("common") {
TEST_CASE("procedural meshes are closed where they should be, with outward normals") {
    for (const auto& [name, mesh] : {std::pair{"icosphere", icosphere(Vec3(1, 2, 3), 2, 2)},
                                     std::pair{"cube", subdivided_cube(Vec3(1, 2, 3), 2, 3)}}) {
        const char* shape = name;  // clang 14 cannot capture a structured binding
        CAPTURE(shape);
        std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
        for (const auto& t : mesh.triangles) {
            const Vec3 n =
                glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]);
            const Vec3 centroid = (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / Real(3);
            CHECK(glm::dot(n, centroid - Vec3(1, 2, 3)) > 0);
            for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
        }
        // Closed and consistently oriented: every directed edge once, and its reverse once.
        for (const auto& [e, n] : directed) {
            CHECK(n == 1);
            CHECK(directed.count({e.second, e.first}) == 1);
        }
    }
    CHECK(icosphere(Vec3(0), 1, 3).triangles.size() == 1280);
    CHECK(subdivided_cube(Vec3(0), 1, 4).triangles.size() == 6 * 16 * 2);
    CHECK(terrain(Vec3(0), 1, 1, 8).triangles.size() == 128);
    CHECK_THROWS_AS(icosphere(Vec3(0), -1, 2), std::invalid_argument);
}

TEST_CASE("bad meshes are rejected, degenerate triangles dropped") {
    MeshData m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
    m.triangles = {{0, 1, 9}};
    CHECK_THROWS_WITH_AS(Mesh{m}, doctest::Contains("uses vertex 9 of 4"), std::invalid_argument);
    m.triangles = {{0, 1, 2}, {0, 1, 3}};  // the second is collinear: zero area
    const Mesh mesh(m);
    CHECK(mesh.dropped_degenerate() == 1);
    CHECK(mesh.data().triangles.size() == 1);
    m.triangles = {{0, 1, 3}};
    CHECK_THROWS_AS(Mesh{m}, std::invalid_argument);
    CHECK_THROWS_AS(Triangle(Vec3(0), Vec3(1, 0, 0), Vec3(2, 0, 0)), std::invalid_argument);
}

TEST_CASE("degenerate polygons are rejected with a clear error") {
    CHECK_THROWS_WITH_AS(Polygon({{0, 0, 0}, {1, 0, 0}}),
                         doctest::Contains("polygon vertices must be in 3..100000, not 2"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(Polygon({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}), doctest::Contains("collinear"),
                         std::invalid_argument);
    CHECK_THROWS_WITH_AS(Polygon({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 1, 0}}), doctest::Contains("same point"),
                         std::invalid_argument);
    CHECK_THROWS_WITH_AS(Polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5}, {0, 1, 0}}), doctest::Contains("is off the plane"),
                         std::invalid_argument);
    CHECK_THROWS_AS(Polygon({{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}}), std::invalid_argument);
    // The vertex named is the one off the plane, even when it is the first.
    CHECK_THROWS_WITH_AS(Polygon({{0, 0, 0.5}, {1, 0, 0}, {1.5, 1, 0}, {0.5, 1.6, 0}, {-0.5, 1, 0}}),
                         doctest::Contains("vertex 0 is off the plane"), std::invalid_argument);
}
}  // TEST_SUITE("common")
