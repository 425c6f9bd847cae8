#pragma once
// Ray-sphere intersection (book §2, course §9.3.1). sphere_roots_textbook, sphere_roots and
// hit(Sphere) are the chapter 02 exercises (solutions/ch02_spheres.cpp).
#include "core/box.hpp"
#include "core/interval.hpp"
#include "core/ray.hpp"
#include "geometry/hit_record.hpp"

namespace rt {

// What the sphere test finds: the ray parameter, and nothing the library cannot derive.
struct SphereHit {
    Real t;
};

// A sphere: geometry only. What it is made of is bound to it by a Surface. A sphere can
// move (chapter 18): its centre goes from `center` at time 0 to `center + motion` at time
// 1 at constant speed, and a ray sees it where it is at the ray's time.
struct Sphere {
    using Hit = SphereHit;  // what its test reports

    Vec3 center;
    Real radius;
    Vec3 motion{0};

    // Throws std::invalid_argument unless the centre and motion are finite and the radius > 0.
    Sphere(const Vec3& center, Real radius, const Vec3& motion = Vec3(0));

    bool moves() const { return motion != Vec3(0); }
    // The sphere standing where this one is at `time`.
    Sphere at(Real time) const {
        Sphere s = *this;
        s.center = center + time * motion;
        s.motion = Vec3(0);
        return s;
    }
};

// Both roots of |e + t d - c|^2 = R^2, t_near <= t_far. False when the line misses
// (negative discriminant); a tangent line gives t_near == t_far. Any way of writing the
// formulas passes (C as f.f - R^2 or (|f| - R)(|f| + R), B or its half, fma or not): roots are
// graded within a stated number of machine epsilons, and compared exactly only where every
// number is exact, so that every way gives the same bits: a tangent with |f| = 5, R = 3 (the
// discriminant exactly 0, both roots exactly 2) and a line tangent at the ray's origin, a
// point of the sphere (b = C = 0: both roots exactly 0). A grazing line whose numbers are not
// exact (|f| = sqrt(26)) may come out as two roots a rounding apart or as a near miss: not graded.

// Exercise 2.1: the course's formula, as printed. Graded on rays where it is accurate (the
// course's own example to 4 machine epsilons, a miss, the exact tangents above, a direction
// that is not unit length); how inaccurate it gets elsewhere is the book's evidence (§2.6),
// not a grade.
bool sphere_roots_textbook(const Ray& ray, const Vec3& center, Real radius, Real& t_near, Real& t_far);

// Exercise 2.2: the same roots, computed without catastrophic cancellation (book §2.3: both
// cures, since each test below defeats one cure alone). What that means in numbers, as the
// tests check it: for a unit sphere 10^4 radii away and rays over 0.999 of its silhouette,
// both roots within 64 machine epsilons (relative) of a long-double reference and no false
// misses (the geometric discriminant's test); for a ray starting 1 outside a sphere of radius
// 3999 and heading in (t_near about 1.48, t_far about 11423), both roots within 64 epsilons
// (relative) too (the stable roots' test); for a ray leaving a sphere's surface, the root at
// its origin within rounding of 0 (512 epsilons of the coordinates' size, measured along the
// normal); the exact tangents above. In q = -(b + sign(b) sqrt(discriminant)), sign(0) is +1,
// as std::copysign(x, b) gives it (-1 for b = -0.0, just as good): never 0, as glm::sign(0)
// is, which makes q = 0 and a false double root for a ray whose closest approach to the
// centre is its origin (b = 0). q = 0 itself happens only on a line tangent at its origin:
// there C/q is 0/0, and the roots are a double 0.
bool sphere_roots(const Ray& ray, const Vec3& center, Real radius, Real& t_near, Real& t_far);

// Exercise 2.3: the first root in the interval (closed: both ends count). True and `result`
// set if there is one; false and `result` untouched if not. Its roots may come from 2.2 or be
// worked out here, under 2.2's rules: exact only where every number is (a unit sphere 5
// ahead: roots 4 and 6, so the interval [4, 4] hits), within the tolerances elsewhere.
bool hit(const Sphere& sphere, const Ray& ray, Interval interval, SphereHit& result);

// How far a computed hit point may lie off the sphere, along its normal, and how far the
// sphere test's near root strays for a ray that starts that close to it (the record's
// `error`, which spawn_ray clears). Both are rounding of numbers the size of the centre's
// coordinates and the radius, not of the hit point's: p = c + R n rounds to a unit in the
// last place of |c| + R, and the test's f . f - R^2 rounds to one of R^2, which is a height
// error of about epsilon R. kSphereErrorEpsilons machine epsilons of |c|_1 + R covers both,
// with margin (book §6.3; tests/test_ch06.cpp measures it from 10^3 to 10^5).
inline constexpr int kSphereErrorEpsilons = 8;
Real sphere_error(const Sphere& sphere);

// The whole record for a sphere hit: point on the sphere, unit outward normal.
HitRecord record(const Sphere& sphere, const Ray& ray, const SphereHit& h, SurfaceRef who = {});

// The box of a sphere; of a moving one, the box of every place it passes through in [0, 1]
// (exercise 18.2), so that a search structure built once stays exact at every time.
Box bounding_box(const Sphere& sphere);

// Exercise 18.2: the smallest box that holds a moving sphere at every time in [0, 1]: its
// centre moves along a straight line, so that is the box of the sphere at time 0 and the
// sphere at time 1 together (for a sphere that does not move, its own box). Compared exactly,
// on numbers every way of taking that union gives exactly.
Box swept_box(const Sphere& sphere);

}  // namespace rt
