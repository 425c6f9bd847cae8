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

// A sphere: geometry only. What it is made of is bound to it by a Surface.
struct Sphere {
    using Hit = SphereHit;  // what its test reports

    Vec3 center;
    Real radius;

    // Throws std::invalid_argument unless the centre is finite and the radius > 0.
    Sphere(const Vec3& center, Real radius);
};

// Both roots of |e + t d - c|^2 = R^2, t_near <= t_far. False when the line misses
// (negative discriminant); a tangent line gives t_near == t_far.

// Exercise 2.1: the course's formula, as printed.
bool sphere_roots_textbook(const Ray& ray, const Vec3& center, Real radius, Real& t_near, Real& t_far);

// Exercise 2.2: the same roots, computed without catastrophic cancellation.
bool sphere_roots(const Ray& ray, const Vec3& center, Real radius, Real& t_near, Real& t_far);

// Exercise 2.3: the first root in the interval. True and `result` set if there is one;
// false and `result` untouched if not.
bool hit(const Sphere& sphere, const Ray& ray, Interval interval, SphereHit& result);

// The whole record for a sphere hit: point on the sphere, unit outward normal.
HitRecord record(const Sphere& sphere, const Ray& ray, const SphereHit& h, SurfaceRef who = {});

Box bounding_box(const Sphere& sphere);

}  // namespace rt
