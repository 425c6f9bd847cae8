// Book §8.1: refraction at a flat interface, Snell's law n sin(theta) = n_t sin(phi). The
// surface is the line y = 0 with the normal n = +y on the side the ray comes from; the
// transmitted direction t is refract's (exercise 8.1) and the part reflected back reflect's
// (exercise 7.1). Both angles are measured from the library's vectors.
#include "kinds.hpp"
#include "shading/optics.hpp"

namespace figures {

Canvas refraction(const rt::Fields& in) {
    const rt::Real n_from = in.number("n_from", rt::limits::index_of_refraction);
    const rt::Real n_to = in.number("n_to", rt::limits::index_of_refraction);
    const rt::Real incidence = in.number("incidence", {"angle of incidence", 0, 89.9, "degrees", ""});
    const double half = double(in.length("surface"));
    const rt::Real a = incidence * rt::Real(M_PI / 180);
    const rt::Vec3 d(std::sin(a), -std::cos(a), 0), n(0, 1, 0);
    rt::Vec3 t;
    if (!rt::refract(d, n, n_from, n_to, t))
        in.fail("incidence", "no transmitted ray at this angle: total internal reflection");
    const rt::Vec3 r = rt::reflect(d, n);

    Canvas c;
    const P2 p{0, 0};
    c.box({-half, -1.2}, {half, 0}, Ink::surface);
    c.line({0, -1.2}, {0, 1.2}, Ink::guide, Stroke::dashed);  // the normal's line
    c.arrow(p - 1.1 * flat(d), p, Ink::camera);
    c.label(p - 1.1 * flat(d), "d", Ink::camera, -8, -4, Anchor::end);
    c.arrow(p, p + 0.8 * flat(n), Ink::normal);
    c.label(p + 0.8 * flat(n), "n", Ink::normal, 6, -8);
    c.arrow(p, p + 1.1 * flat(t), Ink::refracted);
    c.label(p + 1.1 * flat(t), "t", Ink::refracted, 8, -4);
    c.arrow(p, p + 0.6 * flat(r), Ink::reflected, Stroke::dashed);
    c.label(p + 0.6 * flat(r), "reflected part", Ink::reflected, 6, 0, Anchor::start, true);
    c.angle(p, flat(-d), flat(n), 50, Ink::axis);
    c.angle(p, flat(t), flat(-n), 50, Ink::axis);
    c.label(p, "θ = " + number(degrees_between(-d, n), 3) + "°", Ink::axis, -14, 62, Anchor::end);
    c.label(p, "φ = " + number(degrees_between(t, -n), 3) + "°", Ink::axis, 14, -72);
    c.label({-half, 0}, "n₁ = " + number(double(n_from)), Ink::axis, 6, 10);
    c.label({-half, 0}, "n₂ = " + number(double(n_to)), Ink::axis, 6, -24);
    return c;
}

}  // namespace figures
