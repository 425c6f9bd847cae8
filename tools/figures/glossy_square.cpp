// Book §17.1-17.2, course Figure 9.36: the glossy square. Left, seen from the side (the plane
// z = 0): the incoming ray, the normal, the unit mirror direction r (exercise 7.1's reflect,
// normalised as the integrator does) and the square of side a at its tip, edge on; the
// perturbed directions r' are exercise 17.1's glossy_direction at the points the renderer's
// Sampler gives one pixel's samples (sample_square in the glossy dimension, jittered).
// Right, the same square face on, in the library's own frame U, V (recovered from
// glossy_direction itself), with each r' where it crosses the square; hollow: r' points below
// the surface, and the integrator returns black for it (§17.3).
#include "core/sampler.hpp"
#include "kinds.hpp"
#include "render/strata.hpp"
#include "shading/optics.hpp"

#include <string>

namespace figures {

Canvas glossy_square(const rt::Fields& in) {
    const rt::Vec3 n = rt::unit_vector(in.direction("normal"));
    const rt::Vec3 incoming = rt::unit_vector(in.direction("incoming"));
    const rt::Real a = in.number("width", rt::limits::glossy_width);
    const auto [count, side, seed, pixel] = pixel_samples_of(in);
    if (!(glm::dot(incoming, n) < 0)) in.fail("incoming", "must point towards the surface (against the normal)");

    const rt::Vec3 r = rt::unit_vector(rt::reflect(incoming, n));
    // The frame is the library's: glossy_direction moves r by half a unit along U for (1, 1/2)
    // and along V for (1/2, 1).
    const rt::Vec3 U = rt::Real(2) * (rt::glossy_direction(r, 1, rt::Vec2(1, 0.5)) - r);
    const rt::Vec3 V = rt::Real(2) * (rt::glossy_direction(r, 1, rt::Vec2(0.5, 1)) - r);

    Canvas c;
    const rt::Vec3 p(0);
    const rt::Vec3 along = rt::unit_vector(glm::cross(n, rt::Vec3(0, 0, 1)));  // the surface's line in the view
    c.line(flat(p - rt::Real(1.2) * along), flat(p + rt::Real(1.2) * along), Ink::surface);
    c.arrow(flat(p - incoming), flat(p), Ink::camera);
    c.arrow(flat(p), flat(p + rt::Real(0.6) * n), Ink::normal);
    c.label(flat(p + rt::Real(0.6) * n), "n", Ink::normal, 4, 4);
    c.line(flat(r - a / 2 * U), flat(r + a / 2 * U), Ink::axis);
    c.label(flat(r + a / 2 * U), "a", Ink::axis, -6, 2, Anchor::end, true);

    // The face-on square, to the right, magnified to a side of 1.
    const double zoom = 1 / double(a), h = 0.5;
    const P2 mid{2.3, 0.75};
    c.box(mid - P2{h, h}, mid + P2{h, h}, Ink::surface);
    for (int k = 1; k < side; ++k) {
        const double s = -h + 2 * h * k / side;
        c.line(mid + P2{s, -h}, mid + P2{s, h}, Ink::guide, Stroke::dashed);
        c.line(mid + P2{-h, s}, mid + P2{h, s}, Ink::guide, Stroke::dashed);
    }
    c.arrow(mid - P2{h, h + 0.12}, mid + P2{-h + 0.35, -h - 0.12}, Ink::axis);
    c.label(mid + P2{-h + 0.35, -h - 0.12}, "U", Ink::axis, 4, -6);
    c.arrow(mid - P2{h + 0.12, h}, mid + P2{-h - 0.12, -h + 0.35}, Ink::axis);
    c.label(mid + P2{-h - 0.12, -h + 0.35}, "V", Ink::axis, -4, 0, Anchor::end);

    rt::Sampler sampler(seed, pixel);
    sampler.set_strata(count, side, rt::Strata::jittered);
    int below = 0;
    for (int k = 0; k < count; ++k) {
        sampler.start_sample(k);
        const rt::Vec3 r2 = rt::glossy_direction(r, a, rt::sample_square(sampler, rt::Dimension::glossy));
        const bool leaves = glm::dot(r2, n) > 0;
        below += !leaves;
        c.line(flat(p), flat(p + rt::Real(1.15) * r2), leaves ? Ink::reflected : Ink::guide, Stroke::thin);
        const rt::Vec3 off = r2 - r;
        c.dot(mid + zoom * P2{double(glm::dot(off, U)), double(glm::dot(off, V))}, Ink::reflected, !leaves);
    }
    c.arrow(flat(p), flat(r), Ink::axis);
    c.label(flat(r), "r", Ink::axis, 8, -14);
    c.label(mid - P2{0, h + 0.3},
            "the square, face on: a = " + number(double(a)) +
                (below ? ", " + std::to_string(below) + " below the surface" : ""),
            Ink::axis, 0, -22, Anchor::middle, true);
    return c;
}

}  // namespace figures
