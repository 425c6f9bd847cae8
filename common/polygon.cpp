#include "common/polygon.hpp"

#include <cmath>
#include <stdexcept>

namespace rt {

Polygon::Polygon(std::string name, std::vector<Vec3> vertices)
    : Surface(std::move(name)), vertices_(std::move(vertices)) {
    const std::string what = "polygon '" + this->name() + "'";
    const std::size_t m = vertices_.size();
    if (m < 3) throw std::invalid_argument(what + ": needs at least 3 vertices, has " + std::to_string(m));
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
    // Planarity: every vertex within a small fraction of the polygon's size of the plane.
    for (std::size_t i = 0; i < m; ++i)
        if (std::abs(glm::dot(vertices_[i] - vertices_[0], normal_)) > Real(1e-4) * extent)
            throw std::invalid_argument(what + ": vertex " + std::to_string(i) + " is off the plane of the others");
    axes_ = projection_axes(normal_);
    for (const Vec3& p : vertices_) projected_.push_back(Vec2(p[axes_[0]], p[axes_[1]]));
}

Box Polygon::bounding_box() const {
    Box box;
    for (const Vec3& p : vertices_) box.expand(p);
    return box;
}

}  // namespace rt
