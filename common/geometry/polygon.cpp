#include "geometry/polygon.hpp"

#include "geometry/limits.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rt {

namespace {

// The largest distance of a vertex (all but `skip`) from the plane with normal n through
// their centroid, and which vertex it is.
std::pair<Real, std::size_t> worst_distance(const std::vector<Vec3>& v, const Vec3& n, std::size_t skip) {
    Real offset = 0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < v.size(); ++i)
        if (i != skip) offset += glm::dot(v[i] - v[0], n), ++count;
    offset /= Real(count);
    std::pair<Real, std::size_t> worst{0, 0};
    for (std::size_t i = 0; i < v.size(); ++i)
        if (i != skip) worst = std::max(worst, {std::abs(glm::dot(v[i] - v[0], n) - offset), i});
    return worst;
}

Vec3 newell_normal(const std::vector<Vec3>& v, std::size_t skip) {
    std::vector<const Vec3*> kept;
    for (std::size_t i = 0; i < v.size(); ++i)
        if (i != skip) kept.push_back(&v[i]);
    Vec3 n(0);
    for (std::size_t i = 0; i < kept.size(); ++i) {
        const Vec3 &p = *kept[i], &q = *kept[(i + 1) % kept.size()];
        n += Vec3((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y));
    }
    return glm::normalize(n);
}

// Which vertex is off the plane (v.size() if none). The plane fitted to all vertices leans
// towards an outlier, so the one farthest from it need not be the culprit: of the few
// farthest, name the first without which the others lie in a plane.
std::size_t off_plane_vertex(const std::vector<Vec3>& v, const Vec3& n, Real tolerance) {
    const std::size_t none = v.size();
    std::vector<std::pair<Real, std::size_t>> distances;
    {
        Real offset = 0;
        for (const Vec3& p : v) offset += glm::dot(p - v[0], n);
        offset /= Real(v.size());
        for (std::size_t i = 0; i < v.size(); ++i)
            distances.push_back({std::abs(glm::dot(v[i] - v[0], n) - offset), i});
    }
    std::sort(distances.rbegin(), distances.rend());
    if (!(distances[0].first > tolerance)) return none;
    if (v.size() > 3)
        for (std::size_t k = 0; k < std::min<std::size_t>(4, distances.size()); ++k) {
            const std::size_t candidate = distances[k].second;
            if (worst_distance(v, newell_normal(v, candidate), candidate).first <= tolerance) return candidate;
        }
    return distances[0].second;
}

}  // namespace

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
    // Planarity: every vertex within a small fraction of the polygon's size of the plane.
    const Real tolerance = Real(1e-4) * extent;
    if (std::size_t off = off_plane_vertex(vertices_, normal_, tolerance); off != m)
        throw std::invalid_argument(what + ": vertex " + std::to_string(off) + " is off the plane of the others");
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
