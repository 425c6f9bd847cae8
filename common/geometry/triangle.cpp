#include "geometry/triangle.hpp"

#include <cmath>
#include <stdexcept>

namespace rt {

HitRecord triangle_record(const Vec3& a, const Vec3& b, const Vec3& c, const TriangleHit& h, SurfaceRef who,
                          std::uint32_t primitive) {
    HitRecord rec;
    rec.t = h.t;
    // The point from the barycentrics, not from e + t d: it lies in the triangle's plane to
    // within rounding of the vertices, whatever the ray's length.
    rec.p = a + h.beta * (b - a) + h.gamma * (c - a);
    rec.normal = glm::normalize(glm::cross(b - a, c - a));
    rec.shading_normal = rec.normal;
    rec.surface = who.surface;
    rec.material = who.material;
    rec.primitive = primitive;
    rec.has_barycentrics = true;
    rec.beta = h.beta;
    rec.gamma = h.gamma;
    return rec;
}

Triangle::Triangle(const Vec3& a_, const Vec3& b_, const Vec3& c_) : a(a_), b(b_), c(c_) {
    const Vec3 n = glm::cross(b - a, c - a);
    if (!(glm::dot(n, n) > 0) || !std::isfinite(glm::dot(n, n)))
        throw std::invalid_argument("triangle is degenerate (zero area or not finite)");
}

Box bounding_box(const Triangle& tri) {
    Box box;
    box.expand(tri.a);
    box.expand(tri.b);
    box.expand(tri.c);
    return box;
}

}  // namespace rt
