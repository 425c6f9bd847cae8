// Chapter 03 exercises: ray-triangle intersection (book §3, course §9.3.2). Declared in
// common/geometry/triangle.hpp.
#include "core/exercise.hpp"
#include "geometry/triangle.hpp"

#include <cmath>
#include <type_traits>
#include <utility>

namespace rt {

// @book cramer
bool ray_triangle(const Ray& ray, const Vec3& A, const Vec3& B, const Vec3& C, Interval interval, TriangleHit& result) {
    // @exercise 3.1 | ray_triangle | book §3.2
    // The 3x3 system [a-b | a-c | d] (beta, gamma, t) = a - e, in the course's letters.
    const Vec3& d = ray.direction;
    const Real a = A.x - B.x, b = A.y - B.y, c = A.z - B.z;
    const Real dd = A.x - C.x, e = A.y - C.y, f = A.z - C.z;
    const Real g = d.x, h = d.y, i = d.z;
    const Real j = A.x - ray.origin.x, k = A.y - ray.origin.y, l = A.z - ray.origin.z;
    // Six 2x2 minors, each used twice.
    const Real ei_hf = e * i - h * f, gf_di = g * f - dd * i, dh_eg = dd * h - e * g;
    const Real ak_jb = a * k - j * b, jc_al = j * c - a * l, bl_kc = b * l - k * c;
    const Real M = a * ei_hf + b * gf_di + c * dh_eg;
    if (M == 0) return false;  // parallel to the plane, or a degenerate triangle
    // Early exits in the course's order: t first (cheapest to reject in a scene), then gamma,
    // then beta.
    const Real t = -(f * ak_jb + e * jc_al + dd * bl_kc) / M;
    if (!interval.contains(t)) return false;
    const Real gamma = (i * ak_jb + h * jc_al + g * bl_kc) / M;
    if (gamma < 0 || gamma > 1) return false;
    const Real beta = (j * ei_hf + k * gf_di + l * dh_eg) / M;
    if (beta < 0 || beta > 1 - gamma) return false;
    result = TriangleHit{t, beta, gamma};
    return true;
    // @end
}
// @book-end

// @book watertight
bool ray_triangle_watertight(const Ray& ray, const Vec3& A, const Vec3& B, const Vec3& C, Interval interval,
                             TriangleHit& result) {
    // @exercise 3.2 | ray_triangle_watertight | book §3.4
    const Vec3& d = ray.direction;
    // Ray space: the axis where d is largest becomes z; swapping x and y when d_z < 0 keeps
    // the triangle's winding, so the signs of the edge functions keep their meaning.
    const Vec3 ad = glm::abs(d);
    const int kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (d[kz] < 0) std::swap(kx, ky);
    const Real Sx = d[kx] / d[kz], Sy = d[ky] / d[kz], Sz = Real(1) / d[kz];

    // Vertices relative to the origin, sheared so that the ray runs along +z.
    const Vec3 a = A - ray.origin, b = B - ray.origin, c = C - ray.origin;
    const Real ax = a[kx] - Sx * a[kz], ay = a[ky] - Sy * a[kz];
    const Real bx = b[kx] - Sx * b[kz], by = b[ky] - Sy * b[kz];
    const Real cx = c[kx] - Sx * c[kz], cy = c[ky] - Sy * c[kz];

    // 2D edge functions. An edge shared with a neighbour is computed there from the same two
    // sheared vertices in the opposite order: exactly the negated value, so no ray can slip
    // between the two triangles.
    Real U = cx * by - cy * bx;
    Real V = ax * cy - ay * cx;
    Real W = bx * ay - by * ax;
    if constexpr (std::is_same_v<Real, float>) {
        // On an exact zero, redo the products in double: exact there, so the sign is right.
        if (U == 0 || V == 0 || W == 0) {
            U = float(double(cx) * double(by) - double(cy) * double(bx));
            V = float(double(ax) * double(cy) - double(ay) * double(cx));
            W = float(double(bx) * double(ay) - double(by) * double(ax));
        }
    }
    if ((U < 0 || V < 0 || W < 0) && (U > 0 || V > 0 || W > 0)) return false;
    const Real det = U + V + W;
    if (det == 0) return false;

    // Scaled distance: t = T/det, tested against the interval without dividing first.
    const Real T = U * (Sz * a[kz]) + V * (Sz * b[kz]) + W * (Sz * c[kz]);
    const Real t0 = interval.min, t1 = interval.max;
    if (det > 0 ? (T < t0 * det || T > t1 * det) : (T > t0 * det || T < t1 * det)) return false;
    const Real inv = Real(1) / det;
    // U weights vertex A, V vertex B, W vertex C: beta and gamma are V and W.
    result = TriangleHit{T * inv, V * inv, W * inv};
    return true;
    // @end
}
// @book-end

}  // namespace rt
