// Chapter 04 exercises: ray-polygon intersection (§9.3.3). Declared in common/polygon.hpp.
#include "common/exercise.hpp"
#include "common/polygon.hpp"

#include <cmath>

namespace rt {

// @book axes
std::array<int, 2> projection_axes(const Vec3& n) {
    // @exercise 4.1 | projection_axes | book §4.2
    // Erratum: the course compares |z_n| with |x_n| twice; the second test must be |y_n|.
    const Real x = std::abs(n.x), y = std::abs(n.y), z = std::abs(n.z);
    if (z > x && z > y) return {0, 1};  // mostly along z: keep x and y
    if (y > x) return {0, 2};           // mostly along y: keep x and z
    return {1, 2};                      // mostly along x: keep y and z
    // @end
}
// @book-end

// @book crossing
bool inside_polygon_2d(const std::vector<Vec2>& polygon, const Vec2& p) {
    // @exercise 4.2 | inside_polygon_2d | book §4.3
    // Send a ray from p along +x and count the edges it crosses. An edge counts when its end
    // points lie on opposite sides of the line y = p.y, with the upper end "above" only if
    // strictly greater: half-open in y, so a vertex on the line is counted once, not twice.
    bool inside = false;
    const std::size_t m = polygon.size();
    for (std::size_t i = 0, j = m - 1; i < m; j = i++) {
        const Vec2 &a = polygon[i], &b = polygon[j];
        if ((a.y > p.y) != (b.y > p.y)) {
            // x where the edge meets y = p.y; strictly right of p counts.
            const Real x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
            if (x > p.x) inside = !inside;
        }
    }
    return inside;
    // @end
}
// @book-end

// @book polygon-hit
bool Polygon::hit(const Ray& ray, Real t0, Real t1, HitRecord& rec) const {
    // @exercise 4.3 | Polygon::hit | book §4.4
    const Real denominator = glm::dot(ray.direction, normal_);
    if (denominator == 0) return false;  // parallel to the plane
    const Real t = glm::dot(vertices_[0] - ray.origin, normal_) / denominator;
    if (!(t >= t0 && t <= t1)) return false;
    const Vec3 p = ray.at(t);
    if (!inside_polygon_2d(projected_, Vec2(p[axes_[0]], p[axes_[1]]))) return false;
    rec.t = t;
    rec.p = p;
    rec.normal = normal_;
    rec.surface = this;
    rec.material = material();
    rec.has_barycentrics = false;
    rec.primitive = -1;
    return true;
    // @end
}
// @book-end

}  // namespace rt
