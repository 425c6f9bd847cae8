// Chapter 02 exercises: ray-sphere intersection (book §2, course §9.3.1). Declared in
// common/geometry/sphere.hpp.
#include "core/exercise.hpp"
#include "geometry/sphere.hpp"

#include <cmath>

namespace rt {

// @book textbook
bool sphere_roots_textbook(const Ray& ray, const Vec3& center, Real radius, Real& t_near, Real& t_far) {
    // @exercise 2.1 | sphere_roots_textbook | book §2.2
    const Vec3& d = ray.direction;
    const Vec3 ec = ray.origin - center;
    const Real dd = glm::dot(d, d);
    const Real b = glm::dot(d, ec);  // half of B in At^2 + Bt + C
    const Real discriminant = b * b - dd * (glm::dot(ec, ec) - radius * radius);
    if (discriminant < 0) return false;  // checked before any square root
    const Real root = std::sqrt(discriminant);
    t_near = (-b - root) / dd;
    t_far = (-b + root) / dd;
    return true;
    // @end
}
// @book-end

// @book stable
bool sphere_roots(const Ray& ray, const Vec3& center, Real radius, Real& t_near, Real& t_far) {
    // @exercise 2.2 | sphere_roots | book §2.3
    const Vec3& d = ray.direction;
    const Vec3 f = ray.origin - center;
    const Real a = glm::dot(d, d);
    const Real b = glm::dot(f, d);  // half of B
    // (1) The discriminant from the distance h between the centre and the line:
    // b^2 - a(f.f - R^2) = a (R^2 - h^2). h comes from f minus its projection onto d, whose
    // size is that of the sphere, not of the distance to it, and (R - h)(R + h) subtracts
    // numbers no larger than R.
    const Vec3 foot = f - (b / a) * d;
    const Real h = std::sqrt(glm::dot(foot, foot));
    const Real discriminant = a * (radius - h) * (radius + h);
    if (discriminant < 0) return false;
    // (2) Never subtract two nearly equal numbers for the smaller root: q adds two numbers
    // of the same sign, and Vieta (t_near t_far = c/a) gives the other root as c/q.
    const Real q = -(b + std::copysign(std::sqrt(discriminant), b));
    const Real c = glm::dot(f, f) - radius * radius;
    if (q == 0) {  // tangent line through an origin on the sphere: a double root at 0
        t_near = t_far = 0;
        return true;
    }
    const Real t_a = q / a, t_b = c / q;
    t_near = std::min(t_a, t_b);
    t_far = std::max(t_a, t_b);
    return true;
    // @end
}
// @book-end

// @book hit
bool hit(const Sphere& sphere, const Ray& ray, Interval interval, SphereHit& result) {
    // @exercise 2.3 | hit(Sphere) | book §2.4
    // The near root, unless it lies outside the interval (behind the eye, say, when the eye
    // is inside the sphere): then the far one. The library builds the hit record from t.
    Real t_near, t_far;
    if (!sphere_roots(ray, sphere.center, sphere.radius, t_near, t_far)) return false;
    if (interval.contains(t_near)) {
        result = SphereHit{t_near};
        return true;
    }
    if (interval.contains(t_far)) {
        result = SphereHit{t_far};
        return true;
    }
    return false;
    // @end
}
// @book-end

}  // namespace rt
