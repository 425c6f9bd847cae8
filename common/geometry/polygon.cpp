#include "geometry/polygon.hpp"

#include "geometry/limits.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rt {

Polygon::Polygon(std::vector<Vec3> vertices) : vertices_(std::move(vertices)) {
    const std::string what = "polygon";
    const std::size_t m = vertices_.size();
    if (m < 3) throw std::invalid_argument(what + ": needs at least 3 vertices, has " + std::to_string(m));
    if (m > std::size_t(limits::polygon_vertices.max))
        throw std::invalid_argument(what + ": has " + std::to_string(m) + " vertices, more than the limit of " +
                                    std::to_string(limits::polygon_vertices.max));
    for (std::size_t i = 0; i < m; ++i) {
        const Vec3& p = vertices_[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::invalid_argument(what + ": vertex " + std::to_string(i) + " is not finite");
        if (p == vertices_[(i + 1) % m])
            throw std::invalid_argument(what + ": vertices " + std::to_string(i) + " and " +
                                        std::to_string((i + 1) % m) + " are the same point");
    }
    // Newell's method: the area-weighted normal of any simple polygon, convex or not, robust
    // to nearly collinear vertex triples where a single cross product is not.
    Vec3 n(0);
    Real extent = 0;
    for (std::size_t i = 0; i < m; ++i) {
        const Vec3 &p = vertices_[i], &q = vertices_[(i + 1) % m];
        n += Vec3((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y));
        extent = std::max(extent, glm::length(q - p));
    }
    const Real area2 = glm::length(n);  // twice the area
    if (!(area2 > Real(1e-6) * extent * extent))
        throw std::invalid_argument(what + ": has no area (its vertices are collinear)");
    normal_ = n / area2;
    // Planarity: every vertex within a small fraction of the polygon's size of the plane
    // through their centroid. Measured from the centroid, not from vertex 0, so that the
    // vertex named is the one that is off, even when it is vertex 0.
    Real offset = 0;
    for (const Vec3& p : vertices_) offset += glm::dot(p - vertices_[0], normal_);
    offset /= Real(m);
    std::size_t worst = 0;
    Real worst_distance = 0;
    for (std::size_t i = 0; i < m; ++i) {
        const Real distance = std::abs(glm::dot(vertices_[i] - vertices_[0], normal_) - offset);
        if (distance > worst_distance) worst_distance = distance, worst = i;
    }
    if (worst_distance > Real(1e-4) * extent)
        throw std::invalid_argument(what + ": vertex " + std::to_string(worst) + " is off the plane of the others");
    axes_ = projection_axes(normal_);
    projected_.reserve(m);
    for (const Vec3& p : vertices_) projected_.push_back(Vec2(p[axes_[0]], p[axes_[1]]));
}

HitRecord record(const Polygon& polygon, const Ray& ray, const PolygonHit& h, SurfaceRef who) {
    HitRecord rec;
    rec.t = h.t;
    rec.p = ray.at(h.t);
    rec.normal = polygon.normal();
    rec.surface = who.surface;
    rec.material = who.material;
    return rec;
}

Box bounding_box(const Polygon& polygon) {
    Box box;
    for (const Vec3& p : polygon.vertices()) box.expand(p);
    return box;
}

}  // namespace rt
