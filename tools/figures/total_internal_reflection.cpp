// Book §8.1: total internal reflection. Rays leave a point inside the denser medium at
// growing angles to the normal; below the critical angle refract (exercise 8.1) transmits
// them, beyond it it returns false and all the light is reflected (reflect, exercise 7.1).
// The critical angle drawn is where refract starts to return false, found by bisection on
// the library itself.
#include "kinds.hpp"
#include "shading/optics.hpp"

namespace figures {

namespace {

rt::Vec3 upward(double degrees) {
    const double a = degrees * M_PI / 180;
    return rt::Vec3(rt::Real(std::sin(a)), rt::Real(std::cos(a)), 0);
}

}  // namespace

Canvas total_internal_reflection(const rt::Fields& in) {
    const rt::Real n_from = in.number("n_from", rt::limits::index_of_refraction);
    const rt::Real n_to = in.number("n_to", rt::limits::index_of_refraction);
    const std::vector<rt::Real> angles = in.numbers("angles", 5, {"angle", 0, 89, "degrees", ""});
    const double depth = double(in.length("depth"));  // how far below the surface the rays start
    if (!(n_from > n_to)) in.fail("n_from", "total internal reflection needs n_from > n_to");
    const rt::Vec3 n(0, -1, 0);  // the normal on the side the rays come from
    const auto transmits = [&](double degrees) {
        rt::Vec3 t;
        return rt::refract(upward(degrees), n, n_from, n_to, t);
    };
    double lo = 0, hi = 90;  // transmits at lo, not at hi
    for (int k = 0; k < 60; ++k) (transmits((lo + hi) / 2) ? lo : hi) = (lo + hi) / 2;

    Canvas c;
    const P2 source{0, -depth};
    double right = 0;
    for (rt::Real a : angles) right = std::max(right, depth * std::tan(double(a) * M_PI / 180));
    c.box({-0.3 * depth, -depth * 1.15}, {right + 0.3 * depth, 0}, Ink::surface);
    for (rt::Real a : angles) {
        const rt::Vec3 d = upward(double(a));
        const P2 p{depth * std::tan(double(a) * M_PI / 180), 0};
        c.line({p.x, -0.25 * depth}, {p.x, 0.25 * depth}, Ink::guide, Stroke::thin);  // the normal there
        c.arrow(source, p, Ink::camera);
        rt::Vec3 t;
        if (rt::refract(d, n, n_from, n_to, t)) {
            c.arrow(p, p + 0.6 * depth * flat(t), Ink::refracted);
        } else {
            const rt::Vec3 r = rt::reflect(d, n);
            c.arrow(p, p + 0.5 * depth * flat(r), Ink::reflected);
        }
        c.label(p, number(double(a), 3) + "°", Ink::axis, 0, 10, Anchor::middle, true);
    }
    const P2 critical{depth * std::tan(lo * M_PI / 180), 0};
    c.line(source, critical, Ink::axis, Stroke::dashed);
    c.label(source, "dashed: the critical angle θc = " + number(lo, 3) + "°", Ink::axis, 16, -14, Anchor::start, true);
    c.dot(source, Ink::hit);
    c.label({-0.3 * depth, -depth * 1.15}, "n₁ = " + number(double(n_from)), Ink::axis, 6, 8);
    c.label({-0.3 * depth, 0}, "n₂ = " + number(double(n_to)), Ink::axis, 6, 10);
    return c;
}

}  // namespace figures
