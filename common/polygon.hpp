#pragma once
// Ray-polygon intersection (§9.3.3). projection_axes, inside_polygon_2d and Polygon::hit are
// the chapter 04 exercises (solutions/ch04_polygons.cpp).
#include "common/surface.hpp"

#include <array>
#include <vector>

namespace rt {

// Exercise 4.1: the two coordinate axes (0 = x, 1 = y, 2 = z) to keep when projecting a
// polygon with normal n onto a coordinate plane: drop the axis where |n| is largest, so the
// projection has the largest area and never collapses to a line.
std::array<int, 2> projection_axes(const Vec3& n);

// Exercise 4.2: the crossing-number test. True if p is inside the 2D polygon (any simple
// polygon, convex or concave, either winding). On the boundary the rule is half-open: a point
// on an edge or vertex counts as inside exactly when the point nudged infinitesimally right
// (+x) and, by a far smaller step, up (+y) is inside. So two polygons that share an edge
// claim each point of it exactly once: no gaps, no double hits (book §4.3).
bool inside_polygon_2d(const std::vector<Vec2>& polygon, const Vec2& p);

class Polygon : public Surface {
public:
    // Throws std::invalid_argument for fewer than three vertices, non-finite or repeated
    // vertices, zero area, or vertices off a common plane.
    Polygon(std::string name, std::vector<Vec3> vertices);

    // Exercise 4.3: plane hit, then the 2D test in the projection chosen at construction.
    bool hit(const Ray& ray, Real t0, Real t1, HitRecord& rec) const override;
    Box bounding_box() const override;

    const std::vector<Vec3>& vertices() const { return vertices_; }
    const Vec3& normal() const { return normal_; }

private:
    std::vector<Vec3> vertices_;
    Vec3 normal_;                    // unit, by Newell's method: counter-clockwise faces the viewer
    std::array<int, 2> axes_;        // projection_axes(normal_)
    std::vector<Vec2> projected_;    // the vertices in those axes
};

}  // namespace rt
