#pragma once
// Exercise 3.2's watertight test (Woop, Benthin and Wald 2013) with its per-ray work done
// once: which axis the ray runs along and the shear that makes it +z depend on the ray
// alone, and a mesh leaf tests several triangles with the same ray. The fast path's mesh
// leaves use it (geometry/mesh.cpp).
//
// The arithmetic is the reference solution's (solutions/ch03_triangles.cpp), operation for
// operation, so the answers are the same bit for bit: the build has -ffp-contract=off, and
// test_geometry compares the two on 10^5 rays. On the exercises track, while chapter 03 is
// the student's, meshes call the student's exercise 3.2 instead (RTLAB_STUDENT_TRIANGLE):
// chapter 3's golden images grade it through the meshes too.
#include "geometry/triangle.hpp"

#include <type_traits>
#include <utility>

namespace rt {

struct WatertightRay {
    Vec3 origin;
    int kx, ky, kz;
    Real Sx, Sy, Sz;

    explicit WatertightRay(const Ray& ray) : origin(ray.origin) {
        const Vec3& d = ray.direction;
        const Vec3 ad = glm::abs(d);
        kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
        kx = (kz + 1) % 3;
        ky = (kx + 1) % 3;
        if (d[kz] < 0) std::swap(kx, ky);
        Sx = d[kx] / d[kz];
        Sy = d[ky] / d[kz];
        Sz = Real(1) / d[kz];
    }
};

inline bool hit(const WatertightRay& r, const Vec3& A, const Vec3& B, const Vec3& C, Interval interval,
                TriangleHit& result) {
    const Vec3 a = A - r.origin, b = B - r.origin, c = C - r.origin;
    const Real ax = a[r.kx] - r.Sx * a[r.kz], ay = a[r.ky] - r.Sy * a[r.kz];
    const Real bx = b[r.kx] - r.Sx * b[r.kz], by = b[r.ky] - r.Sy * b[r.kz];
    const Real cx = c[r.kx] - r.Sx * c[r.kz], cy = c[r.ky] - r.Sy * c[r.kz];
    Real U = cx * by - cy * bx;
    Real V = ax * cy - ay * cx;
    Real W = bx * ay - by * ax;
    if constexpr (std::is_same_v<Real, float>) {
        if (U == 0 || V == 0 || W == 0) {
            U = float(double(cx) * double(by) - double(cy) * double(bx));
            V = float(double(ax) * double(cy) - double(ay) * double(cx));
            W = float(double(bx) * double(ay) - double(by) * double(ax));
        }
    }
    if ((U < 0 || V < 0 || W < 0) && (U > 0 || V > 0 || W > 0)) return false;
    const Real det = U + V + W;
    if (det == 0) return false;
    const Real T = U * (r.Sz * a[r.kz]) + V * (r.Sz * b[r.kz]) + W * (r.Sz * c[r.kz]);
    const Real t0 = interval.min, t1 = interval.max;
    if (det > 0 ? (T < t0 * det || T > t1 * det) : (T > t0 * det || T < t1 * det)) return false;
    const Real inv = Real(1) / det;
    result = TriangleHit{T * inv, V * inv, W * inv};
    return true;
}

}  // namespace rt
