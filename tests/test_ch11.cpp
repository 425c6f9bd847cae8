// Chapter 11: the uniform grid (course §9.9.3). Where a walk starts, the cells it visits
// (as many as the planes the ray crosses, plus one, up to the cell of its hit), the course's
// Figure 9.23 trap, walls in the grid's own faces met at a grazing angle (the pad, and the
// ray's own start), and the grid against brute force on random rays and on rays through a
// closed mesh's shared edges. The 11.1 tests run no other exercise; every walk runs 11.1.
#include "accel/accel.hpp"
#include "io/scene_file.hpp"
#include "render/integrators.hpp"
#include "render/render.hpp"
#include "support.hpp"
#include "support/accel_check.hpp"
#include "support/source_dir.hpp"
#include "support/wall_rays.hpp"

#include <cmath>

using namespace rt;

namespace {

const std::string kScenes = rt::test::source_dir() + "/chapters/ch11_grid/scenes/";
constexpr AccelKind kGrid[] = {AccelKind::grid};

// Cells, steps and resolutions as vectors, which a failed check prints by value.
glm::ivec3 ints(const std::array<int, 3>& a) {
    return glm::ivec3(a[0], a[1], a[2]);
}

// Spheres at the corners of the box [-4, 4]^3, small enough that rays through the middle
// miss them all: a grid to walk through without stopping.
SurfaceList corners() {
    SurfaceList list;
    for (int k = 0; k < 8; ++k)
        list.add(Sphere(Vec3(k & 1 ? 3.9 : -3.9, k & 2 ? 3.9 : -3.9, k & 4 ? 3.9 : -3.9), Real(0.1)));
    return list;
}

}  // namespace

TEST_SUITE("ch11") {
TEST_CASE("11.1 start: the first cell, the steps, and the first plane along each axis") {
    const SurfaceList list = corners();
    const Grid grid(list, 64);  // 512 cells: 8 a side
    REQUIRE(ints(grid.resolution()) == glm::ivec3(8, 8, 8));
    CHECK(grid.cell_size().x == doctest::Approx(1));
    // From outside, along +x at y = 0.5, z = -2.5: enters cell (0, 4, 1) at x = -4.
    GridWalk w;
    REQUIRE(grid.start(Ray{Vec3(-10, 0.5, -2.5), Vec3(2, 0, 0)}, Interval{}, w));
    CHECK(ints(w.cell) == glm::ivec3(0, 4, 1));
    CHECK(ints(w.step) == glm::ivec3(1, 0, 0));
    CHECK(w.t_max.x == doctest::Approx(3.5));  // the plane x = -3, reached at t = 7 / 2
    CHECK(w.t_max.y == kInfinity);
    CHECK(w.t_max.z == kInfinity);
    // From inside, towards -x, -y, +z, with a -0: the cell holding the origin.
    REQUIRE(grid.start(Ray{Vec3(1.25, -0.75, 2.5), Vec3(-1, -0.5, -Real(0))}, Interval{}, w));
    CHECK(ints(w.cell) == glm::ivec3(5, 3, 6));
    CHECK(ints(w.step) == glm::ivec3(-1, -1, 0));
    CHECK(w.t_max.x == doctest::Approx(0.25));  // back to x = 1
    CHECK(w.t_max.y == doctest::Approx(0.5));   // down to y = -1: 0.25 / 0.5
    CHECK(w.t_max.z == kInfinity);
    // The interval counts: a walk that would start past its end does not start.
    CHECK_FALSE(grid.start(Ray{Vec3(-10, 0.5, -2.5), Vec3(1, 0, 0)}, Interval{0, 5}, w));
    CHECK_FALSE(grid.start(Ray{Vec3(-10, 9, 0), Vec3(1, 0, 0)}, Interval{}, w));  // above the grid
}

TEST_CASE("11.1 start: through the far face, across a corner, from a plane, and where the walk ends") {
    const SurfaceList list = corners();
    const Grid grid(list, 64);
    REQUIRE(ints(grid.resolution()) == glm::ivec3(8, 8, 8));
    GridWalk w;
    // Entering through the face x = 4: the point on it gives index 8, one past the last
    // cell; the first cell is the last one, clamped.
    REQUIRE(grid.start(Ray{Vec3(10, 0.5, -2.5), Vec3(-2, 0, 0)}, Interval{}, w));
    CHECK(ints(w.cell) == glm::ivec3(7, 4, 1));
    CHECK(ints(w.step) == glm::ivec3(-1, 0, 0));
    CHECK(w.t_max.x == doctest::Approx(3.5));  // back to x = 3
    CHECK(w.t_end == doctest::Approx(7));      // out through x = -4
    // Across a corner from outside: the walk starts where the ray enters (at t = 6, through
    // x = -4), not in the cell nearest the origin, and ends where it leaves (t = 13, y = 4).
    REQUIRE(grid.start(Ray{Vec3(-10, -9, 0.5), Vec3(1, 1, 0)}, Interval{}, w));
    CHECK(ints(w.cell) == glm::ivec3(0, 1, 4));
    CHECK(ints(w.step) == glm::ivec3(1, 1, 0));
    CHECK(w.t_max.x == doctest::Approx(7));
    CHECK(w.t_max.y == doctest::Approx(7));
    CHECK(w.t_max.z == kInfinity);
    CHECK(w.t_end == doctest::Approx(13));
    // An interval that ends inside the grid ends the walk there.
    REQUIRE(grid.start(Ray{Vec3(-10, -9, 0.5), Vec3(1, 1, 0)}, Interval{0, 8}, w));
    CHECK(w.t_end == doctest::Approx(8));
    // From a point on the plane z = 2 with d_z = -0 and with +0: the ray never leaves the
    // plane, so no z plane is ever reached (dividing would give 0 / 0 or an infinity of
    // either sign, depending on which plane and which zero).
    for (Real zero : {-Real(0), Real(0)}) {
        REQUIRE(grid.start(Ray{Vec3(1.25, -0.75, 2), Vec3(-1, -0.5, zero)}, Interval{}, w));
        CAPTURE(std::signbit(zero));
        CHECK(ints(w.cell) == glm::ivec3(5, 3, 6));
        CHECK(w.step[2] == 0);
        CHECK(w.t_max.z == kInfinity);
    }
    // And from inside a cell along -y with d_x = -0: x's planes are never reached either.
    REQUIRE(grid.start(Ray{Vec3(1.25, -0.75, 2.5), Vec3(-Real(0), -1, 0)}, Interval{}, w));
    CHECK(ints(w.step) == glm::ivec3(0, -1, 0));
    CHECK(w.t_max.x == kInfinity);
    CHECK(w.t_max.y == doctest::Approx(0.25));
}

TEST_CASE("11.2 a ray visits one cell more than the planes it crosses (Amanatides & Woo)") {
    // An analytic count, not the renderer's: a ray through the whole grid from face to face
    // crosses floor(exit) - floor(entry) planes along each axis (unit cells from -4).
    const SurfaceList list = corners();
    const Grid grid(list, 64);
    rt::test::Rng rng;
    int failures = 0;
    for (int k = 0; k < 1000; ++k) {
        const Vec3 a(-4, rng(-3.5, 3.5), rng(-3.5, 3.5)), b(4, rng(-3.5, 3.5), rng(-3.5, 3.5));
        const Ray ray{a - (b - a), b - a};  // from outside: enters at t = 1, leaves at t = 2
        int planes = 0;
        for (int axis = 0; axis < 3; ++axis)
            planes += int(std::abs(std::floor(std::min(b[axis], Real(3.999)) + 4) - std::floor(a[axis] + 4)));
        traversal_tally = {};
        HitRecord best = no_hit_before(kInfinity);
        const bool hit = grid.walk(list, ray, Interval{}, best);
        CAPTURE(k);
        RT_CHECK_FIRST(failures, !hit);
        RT_CHECK_FIRST(failures, traversal_tally.nodes == std::uint64_t(planes + 1));
    }
    CHECK(failures == 0);
}

TEST_CASE("11.2 the course's Figure 9.23: a hit beyond the current cell must wait") {
    // A tilted triangle reaches over the whole grid, so it is listed in the first cell, but
    // the ray along the x axis meets it only at x = 2.5; a small sphere at x = 1.9 is met
    // first, in a cell after the first. A walk that takes any hit where it finds one
    // returns the triangle; the right walk returns the sphere, as brute force does.
    SurfaceList list;
    const SurfaceId tilted = list.add(Triangle(Vec3(4, -2, -1.5), Vec3(4, 2, -1.5), Vec3(0, 0, 2.5)));
    const SurfaceId ball = list.add(Sphere(Vec3(1.9, 0, 0), Real(0.15)));
    const Grid grid(list, 200);
    REQUIRE(grid.resolution()[0] >= 5);
    const Ray ray{Vec3(-1, 0, 0), Vec3(1, 0, 0)};

    HitRecord wrong = no_hit_before(kInfinity);
    REQUIRE(grid.walk_unchecked(list, ray, Interval{}, wrong));
    CHECK(wrong.surface == tilted);  // the trap is there
    CHECK(wrong.t == doctest::Approx(3.5));

    HitRecord rec, want;
    REQUIRE(grid.hit(list, ray, Interval{}, rec));
    REQUIRE(Accel(list, AccelKind::none).hit(list, ray, Interval{}, want));
    CHECK(want.surface == ball);
    CHECK(rec.surface == ball);
    CHECK(rec.t == want.t);
    CHECK(rec.t == doctest::Approx(2.75));
}

TEST_CASE("11.2 the walk stops in the cell of the first hit: one cell more than the planes crossed before it") {
    // The corner spheres' grid with a wall across it at x = 0.5, in the middle of the fifth
    // column of cells: every ray from the face x = -4 hits the wall, in the cell that holds
    // the point it hits, and the walk ends there. A walk that goes on to the far face (or
    // one cell past the hit) finds the same hit, in more cells than it should visit.
    SurfaceList list = corners();
    list.add(Polygon({Vec3(0.5, -4, -4), Vec3(0.5, 4, -4), Vec3(0.5, 4, 4), Vec3(0.5, -4, 4)}));
    const Grid grid(list, 64);
    REQUIRE(ints(grid.resolution()) == glm::ivec3(8, 8, 8));
    rt::test::Rng rng;
    int failures = 0, counted = 0;
    for (int k = 0; k < 1000; ++k) {
        const Vec3 a(-4, rng(-3.5, 3.5), rng(-3.5, 3.5)), b(4, rng(-3.5, 3.5), rng(-3.5, 3.5));
        const Ray ray{a - (b - a), b - a};                                    // from outside: enters at t = 1
        const Vec3 p = ray.at((Real(0.5) - ray.origin.x) / ray.direction.x);  // where it meets the wall
        // A hit within a hair of a plane may be taken in the cell before it (the pad): not counted.
        if (std::abs(p.y - std::round(p.y)) < Real(1e-3) || std::abs(p.z - std::round(p.z)) < Real(1e-3)) continue;
        int planes = 4;  // x = -3 .. 0
        for (int axis = 1; axis < 3; ++axis) planes += int(std::abs(std::floor(p[axis]) - std::floor(a[axis])));
        traversal_tally = {};
        HitRecord best = no_hit_before(kInfinity);
        const bool hit = grid.walk(list, ray, Interval{}, best);
        CAPTURE(k);
        CAPTURE(ray.origin);
        CAPTURE(ray.direction);
        RT_CHECK_FIRST(failures, hit);
        RT_CHECK_FIRST(failures, traversal_tally.nodes == std::uint64_t(planes + 1));
        ++counted;
    }
    CHECK(counted > 900);
    CHECK(failures == 0);
}

TEST_CASE(
    "11.2 a wall on the grid's far face, met from close by at a grazing angle: each cell searched to its padded exit") {
    // The wall lies in the plane where the walk's last cell ends. Rounding puts the hit a
    // hair past that plane about half the time, and nothing lies beyond it to find the hit
    // in: the search of the last cell must reach past its exit by the pad too (§11.3).
    const rt::test::Walls walls;
    const rt::test::RaySet set = walls.rays(false);
    CHECK(rt::test::disagreements(walls.list, set.rays, set.intervals, kGrid) == 0);
}

TEST_CASE(
    "11.2 a wall on the grid's near face, met from outside at a grazing angle: cells searched from the ray's own "
    "start") {
    // The ray enters the grid through the wall. Rounding puts the hit a hair before the
    // point where the clipped interval starts about half the time: searched from the ray's
    // own start, the first cell finds it; from the clipped start, the walk goes on to the
    // cube's far side.
    const rt::test::Walls walls;
    const rt::test::RaySet set = walls.rays(true);
    CHECK(rt::test::disagreements(walls.list, set.rays, set.intervals, kGrid) == 0);
}

TEST_CASE("11.2 the grid returns brute force's hit on random rays (t, surface and triangle)") {
    const SurfaceList list = rt::test::mixed_scene();
    const rt::test::RaySet set = rt::test::random_rays(rt::test::kRandomRays);
    CHECK(rt::test::disagreements(list, set.rays, set.intervals, kGrid) == 0);
}

TEST_CASE("11.2 rays aimed at a closed mesh's shared edges and vertices: none lost, brute force's hit") {
    SurfaceList list;
    const MeshData data = icosphere(Vec3(0.3, -0.2, 0.1), 2, 3);
    list.add(Mesh(data));
    list.add(Sphere(Vec3(5, 5, 5), 1));  // a second primitive, so the grid is not one mesh's box
    rt::test::RaySet all, crossing;
    rt::test::edge_rays(data, Vec3(0.3, -0.2, 0.1), all, crossing);
    CHECK(rt::test::disagreements(list, all.rays, all.intervals, kGrid) == 0);
    const Accel grid(list, AccelKind::grid);
    int lost = 0;
    for (const Ray& r : crossing.rays) {
        HitRecord rec;
        lost += !grid.hit(list, r, Interval{}, rec);
    }
    CHECK(lost == 0);
}

TEST_CASE("11.2 the chapter's scenes render the same image with the grid as with brute force") {
    for (const char* name : {"atoms", "stadium"}) {
        Scene scene = load_scene_file(kScenes + name + ".json");
        if (std::string(name) == "stadium")
            scene.integrator = make_integrator(Shading::normal);  // cost differs by design
        CAPTURE(name);
        CHECK(rt::test::image_differences(scene, kGrid, 40, 30) == 0);
    }
}
}
