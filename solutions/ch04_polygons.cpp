// Chapter 04 exercises: ray-polygon intersection (book §4, course §9.3.3). Declared in
// common/geometry/polygon.hpp.
#include "core/exercise.hpp"
#include "geometry/polygon.hpp"

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

// The contract (geometry/polygon.hpp, book §4.3): the crossing number with the half-open
// boundary rule, and a shared edge's crossing computed to the same bits by both polygons
// that share it, whichever way each walks it: then every point on or ulps away from a shared
// edge is inside exactly one of the two.
// @book crossing
bool inside_polygon_2d(const std::vector<Vec2>& polygon, const Vec2& p) {
    // @exercise 4.2 | inside_polygon_2d | book §4.3
    // Send a ray from p along +x and count the edges it crosses. An edge counts when its end
    // points lie on opposite sides of the line y = p.y, with the upper end "above" only if
    // strictly greater: half-open in y, so a vertex on the line is counted once, not twice.
    bool inside = false;
    const std::size_t m = polygon.size();
    for (std::size_t i = 0, j = m - 1; i < m; j = i++) {
        // Lower end first: a neighbour walks a shared edge the other way, and the crossing
        // below, computed from a different end, would round differently there.
        const bool rising = polygon[i].y < polygon[j].y;
        const Vec2 &a = rising ? polygon[i] : polygon[j], &b = rising ? polygon[j] : polygon[i];
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
bool hit(const Polygon& polygon, const Ray& ray, Interval interval, PolygonHit& result) {
    // @exercise 4.3 | hit(Polygon) | book §4.4
    const Vec3& n = polygon.normal();
    const Real denominator = glm::dot(ray.direction, n);
    if (denominator == 0) return false;  // parallel to the plane
    const Real t = glm::dot(polygon.vertices()[0] - ray.origin, n) / denominator;
    if (!interval.contains(t)) return false;
    const Vec3 p = ray.at(t);
    const auto& axes = polygon.axes();
    if (!inside_polygon_2d(polygon.projected(), Vec2(p[axes[0]], p[axes[1]]))) return false;
    result = PolygonHit{t};
    return true;
    // @end
}
// @book-end

}  // namespace rt
