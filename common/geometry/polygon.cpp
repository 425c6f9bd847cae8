#include "geometry/polygon.hpp"

#include "geometry/limits.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rt {

namespace {

// Newell's method: the area-weighted normal (not normalised; its length is twice the area)
// of any simple polygon, convex or not, robust to nearly collinear vertex triples where a
// single cross product is not. Vertex `skip` is left out (v.size(): none).
Vec3 newell(const std::vector<Vec3>& v, std::size_t skip) {
    std::vector<std::size_t> ring;
    for (std::size_t i = 0; i < v.size(); ++i)
        if (i != skip) ring.push_back(i);
    Vec3 n(0);
    for (std::size_t k = 0; k < ring.size(); ++k) {
        const Vec3 &p = v[ring[k]], &q = v[ring[(k + 1) % ring.size()]];
        n += Vec3((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y));
    }
    return n;
}

// How far each vertex (but `skip`) lies from the plane with unit normal n through their
// centroid, farthest first.
std::vector<std::pair<Real, std::size_t>> plane_distances(const std::vector<Vec3>& v, const Vec3& n, std::size_t skip) {
    Real offset = 0;
    for (std::size_t i = 0; i < v.size(); ++i)
        if (i != skip) offset += glm::dot(v[i] - v[0], n);
    offset /= Real(v.size() - (skip < v.size()));
    std::vector<std::pair<Real, std::size_t>> d;
    for (std::size_t i = 0; i < v.size(); ++i)
        if (i != skip) d.push_back({std::abs(glm::dot(v[i] - v[0], n) - offset), i});
    std::sort(d.rbegin(), d.rend());
    return d;
}

// Which vertex is off the plane (v.size() if none). The plane fitted to all vertices leans
// towards an outlier, so the one farthest from it need not be the culprit: of the few
// farthest, name the first without which the others lie in a plane.
std::size_t off_plane_vertex(const std::vector<Vec3>& v, const Vec3& n, Real tolerance) {
    const auto d = plane_distances(v, n, v.size());
    if (!(d[0].first > tolerance)) return v.size();
    if (v.size() > 3)
        for (std::size_t k = 0; k < std::min<std::size_t>(4, d.size()); ++k) {
            const std::size_t candidate = d[k].second;
            const Vec3 without = glm::normalize(newell(v, candidate));
            if (plane_distances(v, without, candidate)[0].first <= tolerance) return candidate;
        }
    return d[0].second;
}

}  // namespace

Polygon::Polygon(std::vector<Vec3> vertices) : vertices_(std::move(vertices)) {
    const std::string what = "polygon";
    const std::size_t m = vertices_.size();
    if (!limits::contains(limits::polygon_vertices, double(m)))
        throw std::invalid_argument(what + ": " + limits::refuse(limits::polygon_vertices, double(m)));
    for (std::size_t i = 0; i < m; ++i) {
        const Vec3& p = vertices_[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::invalid_argument(what + ": vertex " + std::to_string(i) + " is not finite");
        if (p == vertices_[(i + 1) % m])
            throw std::invalid_argument(what + ": vertices " + std::to_string(i) + " and " +
                                        std::to_string((i + 1) % m) + " are the same point");
    }
    const Vec3 n = newell(vertices_, m);
    Real extent = 0;
    for (std::size_t i = 0; i < m; ++i) extent = std::max(extent, glm::length(vertices_[(i + 1) % m] - vertices_[i]));
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
    rec.shading_normal = rec.normal;
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
