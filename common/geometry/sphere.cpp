#include "geometry/sphere.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace rt {

Sphere::Sphere(const Vec3& c, Real r, const Vec3& m) : center(c), radius(r), motion(m) {
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z))
        throw std::invalid_argument("sphere: centre must be finite");
    const Vec3 end = c + m;
    if (!std::isfinite(end.x) || !std::isfinite(end.y) || !std::isfinite(end.z))
        throw std::invalid_argument("sphere: motion must be finite");
    if (!(r > 0) || !std::isfinite(r)) throw std::invalid_argument("sphere: radius must be finite and > 0");
}

Real sphere_error(const Sphere& s) {
    const Vec3 c = glm::abs(s.center);
    return Real(kSphereErrorEpsilons) * std::numeric_limits<Real>::epsilon() * (c.x + c.y + c.z + s.radius);
}

HitRecord record(const Sphere& s, const Ray& ray, const SphereHit& h, SurfaceRef who) {
    // (p - c)/R is the unit normal of an exact p. The computed p carries the rounding of
    // e + t d, so normalise, and put p back onto the sphere along it.
    const Vec3 n = glm::normalize(ray.at(h.t) - s.center);
    HitRecord rec;
    rec.t = h.t;
    rec.p = s.center + s.radius * n;
    rec.normal = n;
    rec.shading_normal = n;
    rec.error = sphere_error(s);
    rec.surface = who.surface;
    rec.material = who.material;
    return rec;
}

Box bounding_box(const Sphere& s) {
    if (s.moves()) return swept_box(s);
    const Vec3 r(s.radius);
    return Box{s.center - r, s.center + r};
}

}  // namespace rt
