// Book §7.1: the mirror direction r = d - 2 (d . n) n. The ray's direction d arrives at the
// surface; taking away its part along n once reaches the surface's plane, twice comes back
// out. r is reflect's (exercise 7.1); the construction arrow is r - d.
#include "kinds.hpp"
#include "shading/optics.hpp"

namespace figures {

Canvas reflection(const rt::Fields& in) {
    const rt::Vec3 n = rt::unit_vector(in.direction("normal"));
    const rt::Vec3 d = in.direction("d");
    const double half = double(in.length("surface"));  // half the width of the surface drawn
    if (n.z != 0 || d.z != 0) in.fail("d", "d and the normal must lie in the plane z = 0 (the page)");
    if (glm::dot(d, n) >= 0) in.fail("d", "must point towards the surface (d . n < 0)");
    const rt::Vec3 r = rt::reflect(d, n);

    Canvas c;
    const P2 p{0, 0}, along{-double(n.y), double(n.x)};
    c.polygon(
        {p - half * along, p + half * along, p + half * along - 0.25 * flat(n), p - half * along - 0.25 * flat(n)},
        Ink::surface);
    c.arrow(p - flat(d), p, Ink::camera);
    c.label(p - 0.5 * flat(d), "d", Ink::camera, -8, 4, Anchor::end);
    c.arrow(p, p + flat(n), Ink::normal);
    c.label(p + flat(n), "n", Ink::normal, 6, 0);
    c.arrow(p, p + flat(r), Ink::reflected);
    c.label(p + flat(r), "r = d − 2(d·n)n", Ink::reflected, 6, 4);
    // The construction: d again from p, then r - d = -2 (d . n) n back up to r's tip.
    c.arrow(p, p + flat(d), Ink::guide, Stroke::dashed);
    c.label(p + flat(d), "d", Ink::guide, 6, -14);
    c.arrow(p + flat(d), p + flat(r), Ink::normal, Stroke::dashed);
    c.label(p + flat(d) + 0.3 * flat(r - d), "−2(d·n)n", Ink::normal, 8, 0);
    c.angle(p, flat(-d), flat(n), 44, Ink::axis);
    c.angle(p, flat(n), flat(r), 52, Ink::axis);
    c.label(p + half * along, "θ = " + number(degrees_between(-d, n), 3) + "° on each side of n", Ink::axis, 6, -60,
            Anchor::start, true);
    return c;
}

}  // namespace figures
