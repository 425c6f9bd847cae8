// Geometry the exercises build on but do not implement: meshes and polygon validation.
#include "geometry/mesh.hpp"
#include "geometry/polygon.hpp"
#include "geometry/procedural.hpp"
#include "geometry/shape.hpp"
#include "geometry/triangle.hpp"
#include "io/obj.hpp"
#include "support.hpp"

#include <pcg_random.hpp>

#include <cmath>
#include <map>
#include <random>

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

TEST_CASE("smooth meshes: interpolated vertex normals, the geometric normal kept for offsets") {
    // An icosphere's computed vertex normals interpolate to within a few degrees of the true
    // sphere normal, where its flat facets are off by up to half a facet's angle.
    const Vec3 c(0.5, -1, 2);
    const Mesh flat(icosphere(c, 2, 2));
    const Mesh smooth = flat.smoothed();
    CHECK(smooth.smooth());
    CHECK_FALSE(flat.smooth());
    CHECK(smooth.data().triangles.size() == flat.data().triangles.size());
    pcg32 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    double worst_flat = 1, worst_smooth = 1;
    for (int k = 0; k < 2000; ++k) {
        const Vec3 target = c + Real(1.5) * Vec3{Real(u(rng)), Real(u(rng)), Real(u(rng))};
        const Ray ray{c + Vec3(0, 0, 10), target - (c + Vec3(0, 0, 10))};
        HitRecord a, b;
        const bool ha = hit_record(flat, ray, Interval{}, SurfaceRef{}, a);
        REQUIRE(ha == hit_record(smooth, ray, Interval{}, SurfaceRef{}, b));
        if (!ha) continue;
        const Vec3 truth = unit_vector(b.p - c);
        CHECK(a.shading_normal == a.normal);  // flat: shading is geometric
        CHECK(b.normal == a.normal);          // the geometric normal is unchanged
        worst_flat = std::min(worst_flat, double(glm::dot(a.normal, truth)));
        worst_smooth = std::min(worst_smooth, double(glm::dot(b.shading_normal, truth)));
    }
    CHECK(worst_smooth > 0.9995);  // within 2 degrees
    CHECK(worst_flat < 0.995);     // facets are off by more than 5 degrees
}

TEST_CASE("OBJ vertex normals are used when every corner has one, dropped otherwise") {
    const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn 1 0 1\nvn 0 1 1\nf 1//1 2//2 3//3\n";
    const MeshData with = load_obj_text(obj, "n.obj");
    REQUIRE(with.normals.size() == 3);
    REQUIRE(with.normal_triangles.size() == 1);
    const Mesh mesh(with);
    CHECK(mesh.smooth());
    HitRecord rec;
    // At the triangle's centroid the interpolated normal is the mean of the three.
    REQUIRE(hit_record(mesh, Ray{Vec3(Real(1) / 3, Real(1) / 3, 1), Vec3(0, 0, -1)}, Interval{}, SurfaceRef{}, rec));
    // The file's normals as given (not unit): their mean (1, 1, 3)/3, made unit.
    const Vec3 want = unit_vector(Vec3(1, 1, 3));
    CHECK(rec.shading_normal.x == doctest::Approx(want.x));
    CHECK(rec.shading_normal.z == doctest::Approx(want.z));
    CHECK(rec.normal == Vec3(0, 0, 1));
    const MeshData some = load_obj_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2 3\n", "some.obj");
    CHECK(some.normals.empty());
    CHECK_FALSE(Mesh(some).smooth());
}
