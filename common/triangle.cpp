#include "common/triangle.hpp"

#include <cmath>
#include <stdexcept>

namespace rt {

void fill_triangle_record(const Vec3& a, const Vec3& b, const Vec3& c, const TriangleHit& h,
                          const Surface* surface, HitRecord& rec) {
    rec.t = h.t;
    // The point from the barycentrics, not from e + t d: it lies in the triangle's plane to
    // within rounding of the vertices, whatever the ray's length.
    rec.p = a + h.beta * (b - a) + h.gamma * (c - a);
    rec.normal = glm::normalize(glm::cross(b - a, c - a));
    rec.surface = surface;
    rec.material = surface->material();
    rec.has_barycentrics = true;
    rec.beta = h.beta;
    rec.gamma = h.gamma;
    rec.primitive = -1;
}

Triangle::Triangle(std::string name, const Vec3& a, const Vec3& b, const Vec3& c, TriangleTest test)
    : Surface(std::move(name)), a_(a), b_(b), c_(c), test_(test) {
    const Vec3 n = glm::cross(b - a, c - a);
    if (!(glm::dot(n, n) > 0) || !std::isfinite(glm::dot(n, n)))
        throw std::invalid_argument("triangle '" + this->name() + "' is degenerate (zero area or not finite)");
}

bool Triangle::hit(const Ray& ray, Real t0, Real t1, HitRecord& rec) const {
    TriangleHit h;
    const bool found = intersect_triangle(test_, ray, a_, b_, c_, t0, t1, h);
    if (found) fill_triangle_record(a_, b_, c_, h, this, rec);
    return found;
}

Box Triangle::bounding_box() const {
    Box box;
    box.expand(a_);
    box.expand(b_);
    box.expand(c_);
    return box;
}

}  // namespace rt
