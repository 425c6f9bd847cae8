// Book §1.4: the viewing rays of one column of pixels, seen from the side (the eye looks
// right, v is up): perspective rays all leave the eye and fan out through the window at
// distance d; orthographic rays leave the window itself, parallel. The rays come from
// window_point and perspective_ray or orthographic_ray (exercises 1.2-1.4), and stop where
// hit(Sphere) finds the sphere in front of them.
#include "geometry/sphere.hpp"
#include "kinds.hpp"

namespace figures {

Canvas camera_rays(const rt::Fields& in) {
    const rt::Projection projection = in.choice("projection", rt::kProjectionNames, "projection");
    const rt::Real d = in.length("distance", 1);
    const std::vector<rt::Real> bt = in.numbers("window", 2, rt::limits::coordinate);  // [b, t]
    const int ny = in.integer("ny", {"pixels", 1, 32, "", ""});
    const rt::Real reach = in.length("reach");  // how far a ray that misses is drawn, along -w
    const rt::Fields ball = in.object("sphere");
    const rt::Sphere sphere(ball.vec3("center"), ball.length("radius"));
    ball.done();

    // The camera at the origin looking down -z; the page shows -w across and v up.
    const rt::Vec3 eye(0);
    const rt::Basis uvw = rt::camera_basis(rt::Vec3(0, 0, -1), rt::Vec3(0, 1, 0));
    const auto page = [&](const rt::Vec3& p) {
        return P2{double(glm::dot(p - eye, -uvw.w)), double(glm::dot(p - eye, uvw.v))};
    };
    const bool perspective = projection == rt::Projection::perspective;
    const rt::Window win{-1, 1, bt[0], bt[1]};
    // The window: at distance d for the perspective camera, through the eye for the orthographic one.
    const rt::Real plane = perspective ? d : 0;
    const auto on_window = [&](rt::Real y) {
        const rt::Vec2 s = rt::window_point(rt::Real(0.5), y, 1, ny, win);
        return eye + s.y * uvw.v - plane * uvw.w;
    };

    Canvas c;
    c.circle(page(sphere.center), double(sphere.radius), Ink::surface);
    c.line(page(on_window(0)), page(on_window(rt::Real(ny))), Ink::axis);
    for (int k = 0; k <= ny; ++k) {  // the pixels' edges
        const P2 q = page(on_window(rt::Real(k))), tick{0.03 * double(bt[1] - bt[0]), 0};
        c.line(q - tick, q + tick, Ink::axis, Stroke::thin);
    }
    c.label(page(on_window(rt::Real(ny))), "window", Ink::axis, 0, 10, Anchor::middle);
    for (int j = 0; j < ny; ++j) {
        const rt::Vec2 uv = rt::window_point(rt::Real(0.5), rt::Real(j + 0.5), 1, ny, win);
        const rt::Ray ray = perspective ? rt::perspective_ray(eye, uvw, d, uv) : rt::orthographic_ray(eye, uvw, uv);
        rt::SphereHit h;
        const bool hits = rt::hit(sphere, ray, rt::Interval{0, rt::kInfinity}, h);
        // A miss is drawn to `reach` along the view, whatever the ray's length.
        const rt::Real end = hits ? h.t : reach / glm::dot(ray.direction, -uvw.w);
        c.arrow(page(ray.origin), page(ray.at(end)), Ink::camera, Stroke::thin);
        if (hits) c.dot(page(ray.at(end)), Ink::hit);
        c.dot(page(ray.at(plane / glm::dot(ray.direction, -uvw.w))), Ink::camera, true);
    }
    if (perspective) {
        c.dot(page(eye), Ink::hit);
        c.label(page(eye), "e", Ink::hit, -8, -6, Anchor::end);
        c.line(page(eye), page(eye - d * uvw.w), Ink::guide, Stroke::dashed);
        c.label(page(eye - rt::Real(0.5) * d * uvw.w), "d", Ink::axis, 0, -24, Anchor::middle);
    }
    return c;
}

}  // namespace figures
