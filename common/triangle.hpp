#pragma once
// Ray-triangle intersection (§9.3.2). ray_triangle and ray_triangle_watertight are the
// chapter 03 exercises (solutions/ch03_triangles.cpp).
#include "common/surface.hpp"

#include <memory>

namespace rt {

// Where a ray meets a triangle: e + t d = a + beta (b - a) + gamma (c - a).
struct TriangleHit {
    Real t, beta, gamma;
};

// Exercise 3.1: Cramer's rule with the shared sub-terms and the course's early exits
// (t, then gamma, then beta). True if t is in [t0, t1] and the point is in the triangle.
bool ray_triangle(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c, Real t0, Real t1,
                  TriangleHit& hit);

// Exercise 3.2: the watertight test of Woop, Benthin and Wald (2013). A ray through an edge
// or vertex shared by two triangles (bit-identical vertices) hits at least one of them.
bool ray_triangle_watertight(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c, Real t0,
                             Real t1, TriangleHit& hit);

// Which of the two tests the triangle surfaces use.
enum class TriangleTest { cramer, watertight };

// The one place that chooses between them.
inline bool intersect_triangle(TriangleTest test, const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c,
                               Real t0, Real t1, TriangleHit& hit) {
    return test == TriangleTest::watertight ? ray_triangle_watertight(ray, a, b, c, t0, t1, hit)
                                            : ray_triangle(ray, a, b, c, t0, t1, hit);
}

// Fills rec for a triangle hit: unit geometric normal (b - a) x (c - a), counter-clockwise
// vertices facing the viewer.
void fill_triangle_record(const Vec3& a, const Vec3& b, const Vec3& c, const TriangleHit& h,
                          const Surface* surface, HitRecord& rec);

class Triangle : public Surface {
public:
    Triangle(std::string name, const Vec3& a, const Vec3& b, const Vec3& c,
             TriangleTest test = TriangleTest::watertight);
    bool hit(const Ray& ray, Real t0, Real t1, HitRecord& rec) const override;
    Box bounding_box() const override;

private:
    Vec3 a_, b_, c_;
    TriangleTest test_;
};

}  // namespace rt
