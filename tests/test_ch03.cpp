// Chapter 03: ray-triangle intersection (course §9.3.2).
#include "geometry/mesh.hpp"
#include "geometry/procedural.hpp"
#include "geometry/shape.hpp"
#include "geometry/triangle.hpp"
#include "geometry/triangle_block.hpp"
#include "support.hpp"
#include "support/leaks.hpp"

#include <pcg_random.hpp>

#include <array>
#include <cmath>
#include <map>
#include <random>

using namespace rt;
using rt::test::kEps;

namespace {

// Both exercises, through one signature; each test case checks one of them.
using TriangleFn = bool (*)(const Ray&, const Vec3&, const Vec3&, const Vec3&, Interval, TriangleHit&);

}  // namespace

TEST_SUITE("ch03") {
void course_exercise_2(TriangleFn fn) {
    TriangleHit h{};
    REQUIRE(fn(Ray{Vec3(1, 1, 1), Vec3(-1, -1, -1)}, Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Interval{}, h));
    CHECK(h.t == doctest::Approx(Real(2) / 3).epsilon(4 * kEps));
    CHECK(h.beta == doctest::Approx(Real(1) / 3).epsilon(4 * kEps));
    CHECK(h.gamma == doctest::Approx(Real(1) / 3).epsilon(4 * kEps));
}

void misses_and_intervals(TriangleFn fn) {
    const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
    TriangleHit h{};
    // Beside the triangle (beta + gamma > 1), and behind the origin.
    CHECK_FALSE(fn(Ray{Vec3(1.5, 1.5, 1), Vec3(0, 0, -1)}, a, b, c, Interval{}, h));
    CHECK_FALSE(fn(Ray{Vec3(0.5, 0.5, -1), Vec3(0, 0, -1)}, a, b, c, Interval{}, h));
    // Inside, at t = 4 with |d| = 0.25: only when 4 is in the interval.
    const Ray r{Vec3(0.5, 0.25, 1), Vec3(0, 0, -0.25)};
    REQUIRE(fn(r, a, b, c, Interval{}, h));
    CHECK(h.t == doctest::Approx(4).epsilon(4 * kEps));
    CHECK(h.beta == doctest::Approx(0.25).epsilon(4 * kEps));
    CHECK(h.gamma == doctest::Approx(0.125).epsilon(4 * kEps));
    CHECK_FALSE(fn(r, a, b, c, Interval{0, 3.9}, h));
    CHECK_FALSE(fn(r, a, b, c, Interval{4.1, kInfinity}, h));
    // In the triangle's plane, across its interior: M = 0 (3.1) and det = U + V + W = 0
    // (3.2), which the contract makes a miss, not a division by zero.
    CHECK_FALSE(fn(Ray{Vec3(-1, 0.5, 0), Vec3(1, 0, 0)}, a, b, c, Interval{}, h));
    // Parallel to the plane, below it: M = 0 again. Divided by, it makes t = +inf, which
    // [0, inf] contains, and barycentrics of 0/0 that pass every comparison.
    CHECK_FALSE(fn(Ray{Vec3(0.5, 0.5, -1), Vec3(1, 0, 0)}, a, b, c, Interval{}, h));
    // Every miss leaves the result alone: the library may pass in the best hit so far.
    CHECK(h.t == doctest::Approx(4).epsilon(4 * kEps));
    CHECK(h.beta == doctest::Approx(0.25).epsilon(4 * kEps));
    // Either side: no back-face culling.
    REQUIRE(fn(Ray{Vec3(0.5, 0.25, -1), Vec3(0, 0, 1)}, a, b, c, Interval{}, h));
    CHECK(h.t == doctest::Approx(1).epsilon(4 * kEps));
}

void edges_and_ends(TriangleFn fn) {
    // The erratum of book §3.2: the pseudo-code's tests keep the edges, the text's strict ones
    // lose them. Rays straight down onto the triangle (0,0,0), (2,0,0), (0,2,0) at (x, y) hit at
    // t = 1 with beta = x/2 and gamma = y/2, every number exact (so compared exactly): on each
    // edge (gamma = 0, beta = 0, beta + gamma = 1) and at each vertex.
    const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
    for (const Vec2 xy : {Vec2(1, 0), Vec2(0, 1), Vec2(1, 1), Vec2(0, 0), Vec2(2, 0), Vec2(0, 2)}) {
        TriangleHit h{-1, -1, -1};
        CAPTURE(xy);
        REQUIRE(fn(Ray{Vec3(xy.x, xy.y, 1), Vec3(0, 0, -1)}, a, b, c, Interval{}, h));
        CHECK(h.t == 1);
        CHECK(h.beta == xy.x / 2);
        CHECK(h.gamma == xy.y / 2);
    }
    // The interval is closed (book §2.4): a hit exactly at either end counts.
    const Ray r{Vec3(0.5, 0.25, 1), Vec3(0, 0, -0.25)};  // t = 4 exactly
    for (const Interval iv : {Interval{4, 4}, Interval{0, 4}, Interval{4, kInfinity}}) {
        TriangleHit h{-1, -1, -1};
        CAPTURE(iv);
        REQUIRE(fn(r, a, b, c, iv, h));
        CHECK(h.t == 4);
    }
}

TEST_CASE("3.1 course exercise 2: (1,1,1) + t(-1,-1,-1) hits the triangle at t = 2/3, beta = gamma = 1/3") {
    course_exercise_2(ray_triangle);
}
TEST_CASE("3.2 course exercise 2, watertight") {
    course_exercise_2(ray_triangle_watertight);
}
TEST_CASE("3.1 misses, the interval, parallel rays and non-unit directions") {
    misses_and_intervals(ray_triangle);
}
TEST_CASE("3.2 misses, the interval, parallel rays and non-unit directions") {
    misses_and_intervals(ray_triangle_watertight);
}

TEST_CASE("3.1 edges, vertices and the interval's ends count (the erratum of §3.2)") {
    edges_and_ends(ray_triangle);
}
TEST_CASE("3.2 edges, vertices and the interval's ends count") {
    edges_and_ends(ray_triangle_watertight);
}

TEST_CASE("3.1 and 3.2 agree on random rays") {
    pcg32 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    auto rv = [&] { return Vec3{Real(u(rng)), Real(u(rng)), Real(u(rng))}; };
    int both = 0, disagree = 0, failures = 0;
    for (int k = 0; k < 20000; ++k) {
        const Vec3 a = rv(), b = rv(), c = rv();
        const Ray r{Vec3(0, 0, 3) + rv(), rv() - Vec3(0, 0, 3)};
        TriangleHit h1{}, h2{};
        const bool x = ray_triangle(r, a, b, c, Interval{}, h1),
                   y = ray_triangle_watertight(r, a, b, c, Interval{}, h2);
        if (x != y) {  // allowed only within rounding of an edge
            disagree += std::min({h1.beta, h1.gamma, 1 - h1.beta - h1.gamma, h2.beta, h2.gamma,
                                  1 - h2.beta - h2.gamma}) < -1e-3;
            continue;
        }
        if (!x) continue;
        ++both;
        CAPTURE(r.origin);
        CAPTURE(r.direction);
        CAPTURE(a);
        CAPTURE(b);
        CAPTURE(c);
        RT_CHECK_FIRST(failures, std::abs(h1.t - h2.t) < 1e3 * kEps * (1 + std::abs(h1.t)));
        RT_CHECK_FIRST(failures, std::abs(h1.beta - h2.beta) < Real(1e-3));
        RT_CHECK_FIRST(failures, std::abs(h1.gamma - h2.gamma) < Real(1e-3));
    }
    CHECK(both > 1000);
    CHECK(failures == 0);
    CHECK(disagree == 0);
}

TEST_CASE("Triangle and Mesh records: barycentrics, unit normal, closest triangle") {
    const Triangle t(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0));
    HitRecord rec;
    REQUIRE(hit_record(t, Ray{Vec3(0.25, 0.5, 2), Vec3(0, 0, -1)}, Interval{}, SurfaceRef{2, 1}, rec));
    CHECK(rec.has_barycentrics);
    CHECK(rec.beta == doctest::Approx(0.25));
    CHECK(rec.gamma == doctest::Approx(0.5));
    CHECK(rec.normal == Vec3(0, 0, 1));  // counter-clockwise seen from +z
    CHECK(rec.p == Vec3(0.25, 0.5, 0));
    CHECK(rec.surface == 2);
    CHECK(rec.material == 1);
    CHECK(rec.primitive == kNone);  // a lone triangle is not part of a mesh
    // Two parallel triangles in one mesh: the nearer one wins whatever their order.
    MeshData m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
    m.triangles = {{0, 1, 2}, {3, 4, 5}};
    const Mesh mesh(m);
    REQUIRE(hit_record(mesh, Ray{Vec3(0.2, 0.2, 5), Vec3(0, 0, -1)}, Interval{}, SurfaceRef{}, rec));
    CHECK(rec.t == doctest::Approx(4));
    CHECK(rec.primitive == 1);
    REQUIRE(hit_record(mesh, Ray{Vec3(0.2, 0.2, -5), Vec3(0, 0, 1)}, Interval{}, SurfaceRef{}, rec));
    CHECK(rec.t == doctest::Approx(5));
    CHECK(rec.primitive == 0);
    // Any hit: both triangles are in the way of a ray through them, neither past max.
    CHECK(occluded(mesh, Ray{Vec3(0.2, 0.2, 5), Vec3(0, 0, -1)}, Interval{}));
    CHECK_FALSE(occluded(mesh, Ray{Vec3(0.2, 0.2, 5), Vec3(0, 0, -1)}, Interval{0, 3.9}));
    CHECK_FALSE(occluded(mesh, Ray{Vec3(0.9, 0.9, 5), Vec3(0, 0, -1)}, Interval{}));
}

TEST_CASE("3.2 watertightness: 10^6 rays at shared edges and vertices, zero leaks") {
    // The table in book §3.5 comes from these numbers (and bench/watertight for more).
    const MeshData sphere = icosphere(Vec3(0.1, -0.2, 0.3), 1, 3);
    const MeshData cube = subdivided_cube(Vec3(0.1, -0.2, 0.3), 1.7, 8);
    for (const auto& [name, mesh] : {std::pair{"icosphere", &sphere}, std::pair{"cube", &cube}}) {
        const LeakReport wt = measure_leaks(*mesh, TriangleTest::watertight, 500000, 1);
        const LeakReport cr = measure_leaks(*mesh, TriangleTest::cramer, 500000, 1);
        MESSAGE("Real=" << std::string(real_name()) << " " << std::string(name) << ": " << wt.rays << " rays ("
                        << wt.edge_rays << " at edges, " << wt.vertex_rays << " at vertices): Cramer leaks " << cr.leaks
                        << ", watertight leaks " << wt.leaks);
        CHECK(wt.rays == 500000);
        CHECK(wt.leaks == 0);
    }
}
}  // TEST_SUITE("ch03")

// The fast path (book §10.5) runs exercise 3.2's arithmetic in float on four triangles at
// once and sends only the triangles it keeps to the exercise itself; if it ever dropped one
// the exercise accepts, a mesh would lose hits. Rays through corners and edges (where the
// edge functions are near zero), from near and from 10^4 away, at tiny and huge triangles,
// grazing ones, and intervals that end just at the hit.
TEST_CASE(
    "3.2 the fast path's float filter keeps every triangle the exact test accepts, and is sure only of its hits") {
    pcg32 rng(11);
    std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
    auto rv = [&] { return Vec3{Real(u(rng)), Real(u(rng)), Real(u(rng))}; };
    const std::array<std::uint32_t, 3> corners[4] = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}};
    const std::uint32_t lanes[4] = {0, 1, 2, 3};
    int accepted = 0, plain = 0, plain_sure = 0, dropped_misses = 0, clear_misses = 0, failures = 0;
    for (int k = 0; k < 200000; ++k) {
        const Real size = Real(std::pow(10.0, -4 + 5 * unit(rng)));      // 1e-4 .. 10
        const Real distance = Real(std::pow(10.0, -3 + 7 * unit(rng)));  // 1e-3 .. 1e4
        const Vec3 centre = rv() * Real(std::pow(10.0, 3 * unit(rng)));
        Vec3 p[12];
        for (Vec3& v : p) v = centre + rv() * size;
        if (k % 5 == 0) p[2] = p[0] + (p[1] - p[0]) * Real(2) + rv() * size * Real(1e-3);  // a sliver
        // Aim at a corner, an edge point or an inside point of the first triangle.
        const Real b = Real(unit(rng)), g = k % 3 == 0 ? 0 : Real(unit(rng)) * (1 - b);
        const Vec3 target = k % 7 == 0 ? p[1] : p[0] + b * (p[1] - p[0]) + g * (p[2] - p[0]);
        Vec3 d = glm::normalize(rv());
        if (k % 4 == 0) d = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]) + rv() * Real(1e-3));  // grazing
        const Ray ray{target - d * distance, d * Real(std::pow(10.0, 2 * u(rng)))};
        const Real t_hit = distance / glm::length(ray.direction);
        const Interval intervals[] = {
            {}, {0, t_hit}, {0, t_hit * (1 - 4 * kEps)}, {t_hit, kInfinity}, {-kInfinity, kInfinity}};
        const TriangleBlock block = pack(lanes, p, corners);
        const RayShear shear(ray);
        for (const Interval& iv : intervals) {
            const BlockLanes pass = classify(block, shear, iv);
            const unsigned kept = pass.maybe;
            CHECK((pass.surely & ~pass.maybe) == 0);
            for (int lane = 0; lane < 4; ++lane) {
                TriangleHit h;
                const bool hit = ray_triangle_watertight(ray, p[3 * lane], p[3 * lane + 1], p[3 * lane + 2], iv, h);
                accepted += hit;
                CAPTURE(k);
                CAPTURE(lane);
                const bool kept_it = (kept >> lane & 1u) != 0;
                RT_CHECK_FIRST(failures, (kept_it || !hit));
                // An occlusion query takes a sure lane for a hit without the exact test.
                const bool sure_of_it = (pass.surely >> lane & 1u) != 0;
                RT_CHECK_FIRST(failures, (hit || !sure_of_it));
                // A plain hit: inside a well-shaped triangle, head on, in float's range.
                if (hit && lane == 0 && k % 3 && k % 4 && k % 5 && k % 7 && iv.max == kInfinity &&
                    size > Real(1e-3) * (glm::length(centre) + distance)) {
                    ++plain;
                    plain_sure += sure_of_it;
                }
                // A lane whose triangle lies clearly off the ray should be dropped, or the
                // filter saves nothing: at least where float resolves the triangle well
                // (a thousandth of the coordinates' size; past that it keeps everything).
                const bool resolved = size > Real(1e-3) * (glm::length(centre) + distance);
                if (lane != 0 && !hit && resolved && iv.min == 0 && iv.max == kInfinity) {
                    Box box;
                    for (int v = 0; v < 3; ++v) box.expand(p[3 * lane + v]);
                    const Vec3 half = (box.max - box.min) * Real(0.5), mid = box.min + half;
                    const Vec3 off = mid - ray.origin -
                                     glm::dot(mid - ray.origin, ray.direction) /
                                         glm::dot(ray.direction, ray.direction) * ray.direction;
                    if (glm::length(off) > 2 * glm::length(half)) {
                        ++clear_misses;
                        dropped_misses += !(kept >> lane & 1u);
                    }
                }
            }
        }
    }
    CHECK(failures == 0);
    CHECK(accepted > 100000);
    CHECK(plain > 10000);
    CHECK(plain_sure > 0.6 * plain);  // 74 % when written; below, the shortcut saves little
    CHECK(clear_misses > 5000);
    CHECK(dropped_misses > 0.99 * clear_misses);
}
