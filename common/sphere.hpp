#pragma once
// Ray-sphere intersection (§9.3.1). sphere_roots_textbook, sphere_roots and Sphere::hit
// are the chapter 02 exercises (solutions/ch02_spheres.cpp).
#include "common/surface.hpp"

namespace rt {

// Both roots of |e + t d - c|^2 = R^2, t_near <= t_far. False when the line misses
// (negative discriminant); a tangent line gives t_near == t_far.

// Exercise 2.1: the course's formula, as printed.
bool sphere_roots_textbook(const Ray& ray, const Vec3& center, Real radius, Real& t_near,
                           Real& t_far);

// Exercise 2.2: the same roots, computed without catastrophic cancellation.
bool sphere_roots(const Ray& ray, const Vec3& center, Real radius, Real& t_near, Real& t_far);

class Sphere : public Surface {
public:
    Sphere(std::string name, const Vec3& center, Real radius);

    // Exercise 2.3: the first root in [t0, t1], and the record for it.
    bool hit(const Ray& ray, Real t0, Real t1, HitRecord& rec) const override;
    Box bounding_box() const override;

    const Vec3& center() const { return center_; }
    Real radius() const { return radius_; }

private:
    Vec3 center_;
    Real radius_;
};

}  // namespace rt
