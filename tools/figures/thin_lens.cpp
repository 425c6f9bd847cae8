// Book §16.1, course Figure 9.33: the thin lens seen from the side, depth to the right and
// v up. Every ray is exercise 16.2's thin_lens_ray from a lens point on the v axis through
// one window point (the lens's middle gives exercise 1.4's pinhole ray, drawn dashed); they
// meet on the plane in focus. At the depths `near` and `far`, the spread between the outermost rays
// is the patch the pixel averages there, A |1 - z/f| wide (measured on the rays themselves);
// beyond the plane in focus the patch is the lens upside down. The open dot is the window point.
#include "kinds.hpp"
#include "render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

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
    const rt::Ray pinhole = rt::perspective_ray(eye, uvw, d, uv);
    std::vector<rt::Ray> rays;
    double span = half;
    for (int k = 0; k < count; ++k) {
        const rt::Real l = -1 + 2 * rt::Real(k) / rt::Real(count - 1);
        rays.push_back(rt::thin_lens_ray(eye, uvw, d, uv, aperture, focus, rt::Vec2(0, l)));
        span = std::max(span, std::abs(side(at_depth(rays.back(), far)).y));
    }
    span *= 1.15;
    c.line({0, -half}, {0, half}, Ink::axis);
    c.label({0, -half}, "lens, A = " + number(double(aperture)), Ink::axis, 0, -22, Anchor::middle, true);
    for (const auto& [z, name] : {std::pair{d, "window, d"}, std::pair{focus, "plane in focus, f"}}) {
        c.line({double(z), -span}, {double(z), span}, Ink::guide, Stroke::dashed);
        c.label({double(z), span}, name, Ink::axis, 0, 6, Anchor::middle, true);
    }
    for (const rt::Ray& ray : rays) {
        c.line(side(ray.origin), side(at_depth(ray, far)), Ink::camera, Stroke::thin);
        c.dot(side(ray.origin), Ink::camera);
    }
    c.line(side(pinhole.origin), side(at_depth(pinhole, far)), Ink::axis, Stroke::dashed);
    c.dot(side(at_depth(pinhole, d)), Ink::axis, true);
    // The patch the rays cover at a depth, measured on the rays: A |1 - z/f| wide.
    for (const rt::Real z : {near, far}) {
        double lo = 1e300, hi = -1e300;
        for (const rt::Ray& ray : rays) {
            lo = std::min(lo, side(at_depth(ray, z)).y);
            hi = std::max(hi, side(at_depth(ray, z)).y);
        }
        c.line({double(z), lo}, {double(z), hi}, Ink::normal);
        c.label({double(z), lo}, "z = " + number(double(z)) + ": " + number(hi - lo) + " wide", Ink::normal, 0, -20,
                Anchor::middle, true);
    }
    const rt::Vec3 s_f = at_depth(pinhole, focus);
    c.dot(side(s_f), Ink::hit);
    c.label(side(s_f), "in focus", Ink::hit, 0, 10, Anchor::middle, true);
    c.dot({0, 0}, Ink::axis, true);
    c.label({0, 0}, "e", Ink::axis, -8, 4, Anchor::end);
    return c;
}

}  // namespace figures
