#pragma once
// Ray-polygon intersection (book §4, course §9.3.3). projection_axes, inside_polygon_2d and
// hit(Polygon) are the chapter 04 exercises (solutions/ch04_polygons.cpp).
#include "core/box.hpp"
#include "core/interval.hpp"
#include "core/ray.hpp"
#include "geometry/hit_record.hpp"

#include <array>
#include <vector>

namespace rt {

// Exercise 4.1: the two coordinate axes (0 = x, 1 = y, 2 = z) to keep when projecting a
// polygon with normal n onto a coordinate plane, in increasing order: drop the axis where |n|
// is largest, so the projection has the largest area and never collapses to a line. On a tie
// between the largest components either of them may be dropped (both planes show the same
// area).
std::array<int, 2> projection_axes(const Vec3& n);

// Exercise 4.2: the crossing-number test. True if p is inside the 2D polygon (any simple
// polygon, convex or concave, either winding). On the boundary the rule is half-open: a point
// on an edge or vertex counts as inside exactly when the point nudged infinitesimally right
// (+x) and, by a far smaller step, up (+y) is inside. Each edge's crossing is computed from
// its lower end, whichever way the polygon walks it, so two polygons that share an edge (the
// same two vertices, bit for bit) round its crossing alike: every point that their union
// contains, on or ulps away from the shared edge too, is inside exactly one of them (book
// §4.3). In 3D, hit() keeps this only where both compute the same hit point: coplanar
// polygons in a plane perpendicular to an axis.
bool inside_polygon_2d(const std::vector<Vec2>& polygon, const Vec2& p);

// What the polygon test finds.
struct PolygonHit {
    Real t;
};

// A planar polygon: geometry only, with what every ray test needs computed once.
class Polygon {
public:
    using Hit = PolygonHit;

    // Throws std::invalid_argument for fewer than three or more than limits::polygon_vertices.max
    // vertices, non-finite or repeated vertices, zero area, or vertices off a common plane.
    explicit Polygon(std::vector<Vec3> vertices);

    const std::vector<Vec3>& vertices() const { return vertices_; }
    const Vec3& normal() const { return normal_; }                     // unit, Newell's method
    const std::array<int, 2>& axes() const { return axes_; }           // projection_axes(normal())
    const std::vector<Vec2>& projected() const { return projected_; }  // the vertices in those axes

private:
    std::vector<Vec3> vertices_;
    Vec3 normal_;
    std::array<int, 2> axes_;
    std::vector<Vec2> projected_;
};

// Exercise 4.3: the plane hit, then the 2D test in the polygon's projection. True and
// `result` set if the ray meets the polygon in the interval (closed: both ends count); false
// and untouched if not. No side is culled. t is graded within rounding of the plane's (1e3
// machine epsilons on the tests' random polygons), so the plane may be taken through any of
// the vertices, with its offset n . v or without; exactly only where every number is.
bool hit(const Polygon& polygon, const Ray& ray, Interval interval, PolygonHit& result);

// The whole record: the point e + t d and the polygon's normal.
HitRecord record(const Polygon& polygon, const Ray& ray, const PolygonHit& h, SurfaceRef who = {});

Box bounding_box(const Polygon& polygon);

}  // namespace rt
