// Chapter 01 exercises: viewing rays (book §1, course §9.2). Declared in common/render/camera.hpp.
#include "core/exercise.hpp"
#include "render/camera.hpp"

namespace rt {

// @book basis
Basis camera_basis(const Vec3& view_direction, const Vec3& up) {
    // @exercise 1.1 | camera_basis | book §1.2
    // The eye looks down -w, so w points backwards; u = up x w makes (u, v, w) right-handed
    // with v as close to `up` as the view direction allows.
    const Vec3 w = -glm::normalize(view_direction);
    const Vec3 u = glm::normalize(glm::cross(up, w));
    const Vec3 v = glm::cross(w, u);
    return Basis{u, v, w};
    // @end
}
// @book-end

// @book window
Vec2 window_point(Real x, Real y, int nx, int ny, const Window& win) {
    // @exercise 1.2 | window_point | book §1.3
    // Pixel centres x = i + 0.5 land on u = l + (r - l)(i + 0.5)/nx: the image rectangle
    // [0, nx] x [0, ny] maps onto the window [l, r] x [b, t] edge to edge.
    const Real u = win.l + (win.r - win.l) * x / Real(nx);
    const Real v = win.b + (win.t - win.b) * y / Real(ny);
    return Vec2(u, v);
    // @end
}
// @book-end

// @book rays
Ray orthographic_ray(const Vec3& eye, const Basis& uvw, const Vec2& uv) {
    // @exercise 1.3 | orthographic_ray | book §1.4
    // Parallel rays: every pixel's ray has the same direction and its own origin on the
    // plane through the eye.
    return Ray{eye + uv.x * uvw.u + uv.y * uvw.v, -uvw.w};
    // @end
}

Ray perspective_ray(const Vec3& eye, const Basis& uvw, Real d, const Vec2& uv) {
    // @exercise 1.4 | perspective_ray | book §1.4
    // All rays leave the eye; s - e with s = e + u_s u + v_s v - d w. Not normalised, so
    // that t = 1 is exactly the image plane.
    return Ray{eye, uv.x * uvw.u + uv.y * uvw.v - d * uvw.w};
    // @end
}
// @book-end

}  // namespace rt
