// Chapter 02: ray-sphere intersection (course §9.3.1).
#include "geometry/sphere.hpp"
#include "render/integrators.hpp"
#include "render/render.hpp"
#include "support.hpp"
#include "support/sphere_area.hpp"
#include "support/sphere_reference.hpp"

#include <pcg_random.hpp>

#include <cmath>
#include <memory>
#include <random>

using namespace rt;
using rt::test::kEps;
using rt::test::rel_error;

using rt::test::far_sphere_rays;
using rt::test::reference_roots;

TEST_SUITE("ch02") {
// Each test exercises one function, so a chapter's score counts each exercise on its own.
using RootsFn = bool (*)(const Ray&, const Vec3&, Real, Real&, Real&);

void course_exercise_1(RootsFn roots) {
    const Ray r{Vec3(1, 1, 1), Vec3(-1, -1, -1)};
    const Real want_near = 1 - 1 / std::sqrt(Real(3)), want_far = 1 + 1 / std::sqrt(Real(3));
    Real t_near = 0, t_far = 0;
    REQUIRE(roots(r, Vec3(0), 1, t_near, t_far));
    CHECK(t_near == doctest::Approx(want_near).epsilon(4 * kEps));
    CHECK(t_far == doctest::Approx(want_far).epsilon(4 * kEps));
}

void miss_tangent_scale(RootsFn roots) {
    Real tn = -1, tf = -1;
    // Passes 1.5 from the centre of a unit sphere.
    CHECK_FALSE(roots(Ray{Vec3(-5, 1.5, 0), Vec3(1, 0, 0)}, Vec3(0), 1, tn, tf));
    // Grazes the top of a sphere of radius 3: a double root at t = 2. Every number is exact
    // (|f| = 5, b = -8, A = 4, C = 16), so the discriminant is exactly 0 however C and the
    // discriminant are written, and both roots are exactly 2. (A grazing ray whose |f| is not
    // exact, sqrt(26) say, may come out as two roots a rounding apart, or as a near miss: the
    // contract leaves it free.)
    REQUIRE(roots(Ray{Vec3(-4, 3, 0), Vec3(2, 0, 0)}, Vec3(0), 3, tn, tf));
    CHECK(tn == 2);
    CHECK(tf == 2);
    // Tangent at its own origin, a point on the sphere: a double root at t = 0 (b = C = 0).
    // The stable form's q is 0 there, and C/q would be 0/0 (book §2.3).
    REQUIRE(roots(Ray{Vec3(1, 5, -2), Vec3(0, 0, 0.5)}, Vec3(1, 2, -2), 3, tn, tf));
    CHECK(tn == 0);
    CHECK(tf == 0);
    // Scaling d by 4 divides t by 4: nothing may assume a unit direction.
    REQUIRE(roots(Ray{Vec3(0, 0, 10), Vec3(0, 0, -4)}, Vec3(0, 0, 1), 2, tn, tf));
    CHECK(tn == doctest::Approx(1.75).epsilon(4 * kEps));
    CHECK(tf == doctest::Approx(2.75).epsilon(4 * kEps));
    // Origin at the centre: roots -R/|d| and +R/|d|.
    REQUIRE(roots(Ray{Vec3(3, 3, 3), Vec3(0, 2, 0)}, Vec3(3, 3, 3), 5, tn, tf));
    CHECK(tn == doctest::Approx(-2.5).epsilon(4 * kEps));
    CHECK(tf == doctest::Approx(2.5).epsilon(4 * kEps));
    // Origin at the ray's closest approach to the centre, but not at the centre: b = f.d = 0
    // (exactly), roots -+4/|d|. sign(b) must be +1 or -1 here: with glm::sign(0) = 0, q = 0
    // and the stable form reports a false double root at 0 (or divides by 0).
    REQUIRE(roots(Ray{Vec3(3, 0, 0), Vec3(0, 0, 2)}, Vec3(0), 5, tn, tf));
    CHECK(tn == doctest::Approx(-2).epsilon(4 * kEps));
    CHECK(tf == doctest::Approx(2).epsilon(4 * kEps));
}

TEST_CASE("2.1 course exercise 1: (1,1,1) + t(-1,-1,-1) meets the unit sphere at t = 1 -+ 1/sqrt(3)") {
    course_exercise_1(sphere_roots_textbook);
}
TEST_CASE("2.2 course exercise 1, stable roots") {
    course_exercise_1(sphere_roots);
}
TEST_CASE("2.1 a miss, a tangent, a non-unit direction, an origin at the centre") {
    miss_tangent_scale(sphere_roots_textbook);
}
TEST_CASE("2.2 a miss, a tangent, a non-unit direction, an origin at the centre") {
    miss_tangent_scale(sphere_roots);
}

TEST_CASE("2.3 hit(Sphere) takes the first root inside the interval") {
    const Sphere s(Vec3(0, 0, -5), 1);  // roots 4 and 6 along -z from the origin
    const Ray r{Vec3(0), Vec3(0, 0, -1)};
    SphereHit h{-1};
    REQUIRE(hit(s, r, Interval{0, kInfinity}, h));
    CHECK(h.t == doctest::Approx(4));
    REQUIRE(hit(s, r, Interval{5, kInfinity}, h));  // min past the near root: the far one
    CHECK(h.t == doctest::Approx(6));
    REQUIRE(hit(s, r, Interval{4, 4}, h));  // both ends are in the interval
    CHECK(h.t == doctest::Approx(4));

    // A miss leaves the result alone: the library may pass in the best hit so far.
    SphereHit untouched{-1};
    CHECK_FALSE(hit(s, r, Interval{0, 3.5}, untouched));                             // both roots past max
    CHECK_FALSE(hit(s, r, Interval{6.5, kInfinity}, untouched));                     // both roots before min
    CHECK_FALSE(hit(s, Ray{Vec3(0), Vec3(0, 0, 1)}, Interval{}, untouched));         // sphere behind the eye
    CHECK_FALSE(hit(s, Ray{Vec3(0, 3, 0), Vec3(0, 0, -1)}, Interval{}, untouched));  // passes above it
    CHECK(untouched.t == -1);

    // The record the library builds from that t.
    const HitRecord rec = record(s, r, SphereHit{4}, SurfaceRef{7, 3});
    CHECK(rec.t == 4);
    CHECK(rec.p == Vec3(0, 0, -4));
    CHECK(rec.normal == Vec3(0, 0, 1));  // unit, pointing out, towards the eye
    CHECK(rec.surface == 7);
    CHECK(rec.material == 3);
    CHECK_FALSE(rec.has_barycentrics);
    CHECK(record(s, r, SphereHit{6}).normal == Vec3(0, 0, -1));  // still pointing out of the sphere
}

TEST_CASE("2.3 the eye inside the sphere sees the far root") {
    const Sphere s(Vec3(0), 4);
    SphereHit h{-1};
    REQUIRE(hit(s, Ray{Vec3(1, 0, 0), Vec3(0, 0, -2)}, Interval{}, h));
    CHECK(h.t == doctest::Approx(std::sqrt(15.0) / 2));
}

TEST_CASE("2.3 hit points lie on the sphere and normals are unit length") {
    const Sphere s(Vec3(1, -2, 3), 0.75);
    pcg32 rng(3);
    std::uniform_real_distribution<double> unit(-1, 1);
    int hits = 0, bad = 0;
    for (int k = 0; k < 2000; ++k) {
        const Vec3 origin{Real(4 * unit(rng)), Real(4 * unit(rng)), 10};
        const Vec3 aim = s.center + Vec3{Real(unit(rng)), Real(unit(rng)), Real(unit(rng))};
        const Ray r{origin, aim - origin};
        HitRecord rec;
        if (!hit_record(s, r, Interval{}, SurfaceRef{}, rec)) continue;
        ++hits;
        const bool ok = std::abs(glm::length(rec.normal) - 1) < 4 * kEps &&
                        std::abs(glm::length(rec.p - s.center) - s.radius) < 8 * kEps &&
                        glm::dot(rec.normal, r.direction) < 0;  // seen from outside: facing the eye
        if (!ok && bad++ == 0) {
            CAPTURE(origin);
            CAPTURE(r.direction);
            CHECK(ok);
        }
    }
    CHECK(bad == 0);
    CHECK(hits > 500);
}

TEST_CASE("2.2 stress: a sphere 10^4 radii away agrees with a long-double reference") {
    // Tolerance: relative error of t_near at most 64 machine epsilons of Real (6e-6 in
    // float, 1e-14 in double), with no false misses, for rays over 0.999 of the silhouette.
    Real worst = 0;
    int misses = 0, n = 0;
    Ray first_missed{}, worst_ray{};
    Vec2 worst_roots{0};
    glm::dvec2 worst_reference{0};
    far_sphere_rays(1e4, Real(0.999), 20000, [&](const Ray& r, const Vec3& c) {
        long double ref_near = 0, ref_far = 0;
        REQUIRE(reference_roots(r, c, 1, ref_near, ref_far));
        Real tn, tf;
        ++n;
        if (!sphere_roots(r, c, 1, tn, tf)) {
            if (misses++ == 0) first_missed = r;
            return;
        }
        const Real error = std::max(rel_error(tn, ref_near), rel_error(tf, ref_far));
        if (error > worst) {
            worst = error;
            worst_ray = r;
            worst_roots = Vec2(tn, tf);
            worst_reference = glm::dvec2(double(ref_near), double(ref_far));
        }
    });
    MESSAGE("stable form, Real=" << std::string(real_name()) << ": worst relative error " << worst << " = "
                                 << worst / kEps << " eps over " << n << " rays");
    const Vec3 centre = glm::normalize(Vec3(0.6, 0.3, -0.74)) * Real(1e4);  // radius 1
    CAPTURE(centre);
    {
        CAPTURE(first_missed);  // the reference hits every one of these rays
        CHECK(misses == 0);
    }
    CAPTURE(worst_ray);
    CAPTURE(worst_roots);
    CAPTURE(worst_reference);
    CHECK(worst <= 64 * kEps);
}

TEST_CASE("2.2 one cure is not enough: a ray starting just outside a big sphere keeps its near root's digits") {
    // Book §2.3: the far sphere needs the geometric discriminant, and this ray the stable
    // roots. Its origin is 1 outside a sphere of radius 3999 (f = (2400, 3200, 0), |f| = 4000,
    // C = 7999: every input exact, in float too) and it heads inwards, so t_near (about 1.48)
    // is tiny beside t_far (about 11423): (-b - root)/A subtracts two numbers that agree to
    // three digits and keeps the rounding of the larger (about 2000 epsilons in double, 470
    // in float), while q and C/q add and divide (under 1). The contract: 64 epsilons.
    const Vec3 centre(10, -20, 30);
    const Ray r{centre + Vec3(2400, 3200, 0), Vec3(-0.375, -0.5625, 0.125)};
    long double want_near = 0, want_far = 0;
    REQUIRE(reference_roots(r, centre, 3999, want_near, want_far));
    Real tn = 0, tf = 0;
    REQUIRE(sphere_roots(r, centre, 3999, tn, tf));
    CAPTURE(r);
    CAPTURE(double(want_near));
    CAPTURE(double(want_far));
    CHECK(std::abs(tn - want_near) / want_near <= 64 * kEps);
    CHECK(std::abs(tf - want_far) / want_far <= 64 * kEps);
}

TEST_CASE("2.2 stress: rays leaving a sphere's surface find t_near close to 0") {
    // Secondary rays (shadows, reflections) start on a surface: c is nearly 0 and the
    // small root must come out small, not swamped by the rounding of the large one.
    pcg32 rng(11);
    std::uniform_real_distribution<double> unit(-1, 1);
    const Vec3 c(100, -50, 25);
    const Real R = 10;
    int failures = 0;
    for (int k = 0; k < 1000; ++k) {
        const Vec3 n = glm::normalize(Vec3{Real(unit(rng)), Real(unit(rng)), Real(unit(rng))});
        const Ray r{c + R * n, Vec3{Real(unit(rng)), Real(unit(rng)), Real(unit(rng))}};
        Real tn, tf;
        CAPTURE(r.origin);
        CAPTURE(r.direction);
        const bool found = sphere_roots(r, c, R, tn, tf);
        RT_CHECK_FIRST(failures, found);
        if (!found) continue;
        const Real at_origin = std::abs(tn) < std::abs(tf) ? tn : tf;
        // The origin is on the sphere to within rounding of c + R n (|c| + R ~ 120): the root
        // puts it there to within that, measured along the normal (a grazing ray may travel
        // further for the same offset from the surface).
        RT_CHECK_FIRST(failures, std::abs(at_origin * glm::dot(r.direction, n)) < 512 * kEps * 120);
    }
    CHECK(failures == 0);
}

TEST_CASE("analytic: an orthographic sphere covers pi R^2 of the window") {
    // Count the pixels whose centre ray hits, and compare with the disk's area in pixels.
    // The error is bounded by the pixels the silhouette crosses: about its perimeter.
    const test::SphereArea a = test::orthographic_sphere_area();
    MESSAGE("covered " << a.covered << " pixels, disk area " << a.disk << ", perimeter " << a.perimeter);
    CHECK(std::abs(a.covered - a.disk) < a.perimeter);
    CHECK(std::abs(a.covered - a.disk) < 0.01 * a.disk);
}
}  // TEST_SUITE("ch02")
