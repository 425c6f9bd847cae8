#pragma once
// Ray-triangle intersection (book §3, course §9.3.2). ray_triangle and
// ray_triangle_watertight are the chapter 03 exercises (solutions/ch03_triangles.cpp).
#include "core/box.hpp"
#include "core/interval.hpp"
#include "core/ray.hpp"
#include "geometry/hit_record.hpp"

namespace rt {

// Where a ray meets a triangle: e + t d = a + beta (b - a) + gamma (c - a).
struct TriangleHit {
    Real t, beta, gamma;
};

// What both exercises are graded on: t in the interval (closed: both ends count) and the point
// in the triangle, edges and vertices included (beta >= 0, gamma >= 0, beta + gamma <= 1: the
// course's pseudo-code, not its text's strict inequalities, book §3.2); t, beta and gamma
// within a few machine epsilons on the course's example, within rounding of each other on
// random rays; compared exactly only where every number is exact, so that any way of
// writing the determinants gives the same bits: rays straight down onto a triangle with
// corners (0,0,0), (2,0,0), (0,2,0), through its edges and vertices and at an interval's ends.

// Exercise 3.1: Cramer's rule with the shared sub-terms and the course's early exits
// (t, then gamma, then beta). True if t is in the interval and the point is in the triangle.
// A zero determinant M (a ray parallel to the triangle's plane or in it) is a miss. The order
// of the exits and the grouping of the minors (as cross products, say) are free.
bool ray_triangle(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c, Interval interval, TriangleHit& result);

// Exercise 3.2: the watertight test of Woop, Benthin and Wald (2013). A ray through an edge
// or vertex shared by two triangles (bit-identical vertices) hits at least one of them. A
// zero determinant det = U + V + W (all three edge functions 0: a ray in the triangle's plane)
// is a miss, even for a ray that runs across the triangle inside that plane.
bool ray_triangle_watertight(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c, Interval interval,
                             TriangleHit& result);

// Which of the two tests to use, for the benchmarks and the leak measurements that compare
// them. Shapes always use the watertight one.
enum class TriangleTest { cramer, watertight };

inline bool intersect_triangle(TriangleTest test, const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c,
                               Interval interval, TriangleHit& result) {
    return test == TriangleTest::watertight ? ray_triangle_watertight(ray, a, b, c, interval, result)
                                            : ray_triangle(ray, a, b, c, interval, result);
}

// The whole record for a triangle hit: unit geometric normal (b - a) x (c - a), so
// counter-clockwise vertices face the viewer.
HitRecord triangle_record(const Vec3& a, const Vec3& b, const Vec3& c, const TriangleHit& h, SurfaceRef who,
                          std::uint32_t primitive = kNone);

// One triangle: geometry only.
struct Triangle {
    using Hit = TriangleHit;

    Vec3 a, b, c;

    // Throws std::invalid_argument for a degenerate (zero-area) or non-finite triangle.
    Triangle(const Vec3& a, const Vec3& b, const Vec3& c);
};

inline bool hit(const Triangle& tri, const Ray& ray, Interval interval, TriangleHit& result) {
    return ray_triangle_watertight(ray, tri.a, tri.b, tri.c, interval, result);
}
inline HitRecord record(const Triangle& tri, const Ray&, const TriangleHit& h, SurfaceRef who = {}) {
    return triangle_record(tri.a, tri.b, tri.c, h, who);
}
Box bounding_box(const Triangle& tri);

}  // namespace rt
