// Book §16.1, course Figure 9.33: the thin lens seen from the side, depth to the right and
// v up. Every ray is exercise 16.2's thin_lens_ray from a lens point on the v axis through
// one window point (the lens's middle gives exercise 1.4's pinhole ray, drawn dashed); they
// meet on the plane in focus. At the depth of `near`, the spread between the outermost rays
// is the patch the pixel averages there, A |1 - z/f| wide (measured on the rays themselves).
#include "kinds.hpp"
#include "render/camera.hpp"

namespace figures {

Canvas thin_lens(const rt::Fields& in) {
    const rt::Real aperture = in.length("aperture"), focus = in.length("focus"), d = in.length("d");
    const rt::Real v_s = in.number("window_v", rt::limits::coordinate);
    const int count = in.integer("lens_points", {"lens points", 2, 33, "", ""});
    const rt::Real near = in.length("near"), far = in.length("far");
    if (!(near < focus && focus < far)) in.fail("far", "needs near < focus < far");

    const rt::Vec3 eye(0);
    const rt::Basis uvw = rt::camera_basis(rt::Vec3(0, 0, -1), rt::Vec3(0, 1, 0));
    const rt::Vec2 uv(0, v_s);
    auto side = [&](const rt::Vec3& p) {
        return P2{double(-glm::dot(p - eye, uvw.w)), double(glm::dot(p - eye, uvw.v))};
    };
    // A ray's point at a depth: depth = t d, for every ray the lens makes (book §16.1).
    auto at_depth = [&](const rt::Ray& ray, rt::Real z) { return ray.at(z / d); };

    Canvas c;
    const double half = double(aperture) / 2;
    const double span = double(far) * 0.35;
    c.line({0, -half}, {0, half}, Ink::axis);
    c.label({0, -half}, "lens, A = " + number(double(aperture)), Ink::axis, 0, -22, Anchor::middle, true);
    for (const auto& [z, name] : {std::pair{d, "window, d"}, std::pair{focus, "plane in focus, f"}}) {
        c.line({double(z), -span}, {double(z), span}, Ink::guide, Stroke::dashed);
        c.label({double(z), span}, name, Ink::axis, 0, 6, Anchor::middle, true);
    }
    const rt::Ray pinhole = rt::perspective_ray(eye, uvw, d, uv);
    c.line(side(pinhole.origin), side(at_depth(pinhole, far)), Ink::guide, Stroke::dashed);
    double lo = 1e300, hi = -1e300;
    for (int k = 0; k < count; ++k) {
        const rt::Real l = -1 + 2 * rt::Real(k) / rt::Real(count - 1);
        const rt::Ray ray = rt::thin_lens_ray(eye, uvw, d, uv, aperture, focus, rt::Vec2(0, l));
        c.line(side(ray.origin), side(at_depth(ray, far)), Ink::camera, Stroke::thin);
        c.dot(side(ray.origin), Ink::camera);
        const double y = double(glm::dot(at_depth(ray, near) - eye, uvw.v));
        lo = std::min(lo, y);
        hi = std::max(hi, y);
    }
    const rt::Vec3 s_f = at_depth(pinhole, focus);
    c.dot(side(s_f), Ink::hit);
    c.label(side(s_f), "sharp", Ink::hit, 6, 8, Anchor::start, true);
    c.line({double(near), lo}, {double(near), hi}, Ink::normal);
    c.label({double(near), lo}, "patch at z = " + number(double(near)) + ": " + number(hi - lo), Ink::normal, 0, -20,
            Anchor::middle, true);
    c.dot({0, 0}, Ink::axis, true);
    c.label({0, 0}, "e", Ink::axis, -8, 4, Anchor::end);
    return c;
}

}  // namespace figures
