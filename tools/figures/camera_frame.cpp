// Book §1.2-1.4: the camera frame (u, v, w) at the eye, the image window at distance d down
// -w with its pixels, and one pixel's perspective ray. The frame comes from camera_basis, the
// pixel's window point from window_point and the ray from perspective_ray (exercises 1.1,
// 1.2, 1.4); the ray crosses the window at t = 1.
#include "kinds.hpp"

namespace figures {

Canvas camera_frame(const rt::Fields& in) {
    const rt::Vec3 eye = in.vec3("eye");
    const rt::Basis uvw = rt::camera_basis(in.direction("view"), in.direction("up"));
    const rt::Real d = in.length("distance");
    const std::vector<rt::Real> lrbt = in.numbers("window", 4, rt::limits::coordinate);
    const rt::Window win{lrbt[0], lrbt[1], lrbt[2], lrbt[3]};
    const int nx = in.integer("nx", {"pixels", 1, 16, "", ""}), ny = in.integer("ny", {"pixels", 1, 16, "", ""});
    const int i = in.integer("i", {"pixel column", 0, double(nx - 1), "", ""});
    const int j = in.integer("j", {"pixel row", 0, double(ny - 1), "", ""});
    const rt::Real axis = in.length("axis");    // how long the frame's arrows are drawn
    const rt::Real reach = in.length("reach");  // how far the ray is drawn, in t
    const View3 view(in.direction("look_from"), rt::Vec3(0, 1, 0));

    Canvas c;
    // The window's points in the world: e + u_s u + v_s v - d w.
    const auto on_window = [&](rt::Real x, rt::Real y) {
        const rt::Vec2 s = rt::window_point(x, y, nx, ny, win);
        return view(eye + s.x * uvw.u + s.y * uvw.v - d * uvw.w);
    };
    c.polygon({on_window(0, 0), on_window(nx, 0), on_window(nx, ny), on_window(0, ny)}, Ink::surface);
    c.polygon({on_window(i, j), on_window(i + 1, j), on_window(i + 1, j + 1), on_window(i, j + 1)}, Ink::camera);
    for (int k = 1; k < nx; ++k) c.line(on_window(k, 0), on_window(k, ny), Ink::surface, Stroke::thin);
    for (int k = 1; k < ny; ++k) c.line(on_window(0, k), on_window(nx, k), Ink::surface, Stroke::thin);
    c.label(on_window(0, 0), "(l, b)", Ink::surface, -6, -18, Anchor::end);
    c.label(on_window(nx, ny), "(r, t)", Ink::surface, 6, 4);

    const P2 e = view(eye);
    c.line(e, view(eye - d * uvw.w), Ink::guide, Stroke::dashed);
    c.label(view(eye - rt::Real(0.5) * d * uvw.w), "d", Ink::axis, 0, 8, Anchor::middle);
    const rt::Ray ray = rt::perspective_ray(eye, uvw, d, rt::window_point(i + 0.5, j + 0.5, nx, ny, win));
    c.arrow(e, view(ray.at(reach)), Ink::camera);
    c.dot(view(ray.at(1)), Ink::hit);
    c.label(view(ray.at(1)), "s (t = 1)", Ink::hit, 10, -22, Anchor::start, true);
    c.label(view(ray.at(reach)), "pixel (" + std::to_string(i) + ", " + std::to_string(j) + ")'s ray", Ink::camera, 6,
            6);
    c.arrow(e, view(eye + axis * uvw.u), Ink::axis);
    c.arrow(e, view(eye + axis * uvw.v), Ink::axis);
    c.arrow(e, view(eye + axis * uvw.w), Ink::axis);
    c.label(view(eye + axis * uvw.u), "u", Ink::axis, 4, 4);
    c.label(view(eye + axis * uvw.v), "v", Ink::axis, 4, 4);
    c.label(view(eye + axis * uvw.w), "w", Ink::axis, 4, 4);
    c.dot(e, Ink::hit);
    c.label(e, "e", Ink::hit, -8, -18, Anchor::end);
    return c;
}

}  // namespace figures
