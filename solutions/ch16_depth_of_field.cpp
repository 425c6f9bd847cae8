// Chapter 16 exercises: depth of field (book §16, course §9.11.3). Declared in
// common/render/camera.hpp.
#include "core/exercise.hpp"
#include "render/camera.hpp"

#include <cmath>
#include <numbers>

namespace rt {

// @book lens-point
Vec2 lens_point(const Vec2& u, LensShape shape) {
    // @exercise 16.1 | lens_point | book §16.2
    const Vec2 square = Real(2) * u - Vec2(1);  // [-1, 1)^2, centred on the lens's middle
    if (shape == LensShape::square) return square;
    // The disk: Shirley and Chiu's concentric map sends each square ring around the centre
    // to the circle of the same radius, so strata stay compact (a polar map would stretch them).
    const Real a = square.x, b = square.y;
    if (a == 0 && b == 0) return Vec2(0);
    const Real quarter = std::numbers::pi_v<Real> / 4;
    Real r, phi;
    if (std::abs(a) > std::abs(b)) {
        r = a;
        phi = quarter * (b / a);
    } else {
        r = b;
        phi = 2 * quarter - quarter * (a / b);
    }
    return Vec2(r * std::cos(phi), r * std::sin(phi));
    // @end
}
// @book-end

// @book thin-lens
Ray thin_lens_ray(const Vec3& eye, const Basis& uvw, Real d, const Vec2& uv, Real aperture, Real focus,
                  const Vec2& lens) {
    // @exercise 16.2 | thin_lens_ray | book §16.1
    // The pinhole ray's direction reaches the image plane (distance d) at parameter 1, so the
    // plane in focus at parameter focus / d, at eye + (focus / d) pinhole. From the lens point
    // eye + offset, the direction towards it, scaled by d / focus so that it keeps the pinhole
    // direction's length: pinhole - (d / focus) offset. Written from the eye, not as the
    // difference of two far-away points, it keeps its precision anywhere in the scene.
    const Vec3 pinhole = -d * uvw.w + uv.x * uvw.u + uv.y * uvw.v;
    const Vec3 offset = (aperture / 2) * (lens.x * uvw.u + lens.y * uvw.v);
    return Ray{eye + offset, pinhole - (d / focus) * offset};
    // @end
}
// @book-end

}  // namespace rt
