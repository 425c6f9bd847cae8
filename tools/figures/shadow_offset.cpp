// Book §6.2-6.3: why a shadow ray needs an offset. The surface is seen edge on (the plane
// y = 0). Rounding puts the computed hit p a little off the surface, here below it (drawn
// far larger than it is). A shadow ray from p itself meets its own surface on the way to the
// light: the Polygon's hit test (exercise 4.3) finds it, and the point is wrongly shadowed
// (acne). Started by spawn_ray with the normal offset, at p + epsilon n, the same ray leaves
// the surface behind and reaches the light.
#include "core/offset.hpp"
#include "geometry/polygon.hpp"
#include "kinds.hpp"

namespace figures {

Canvas shadow_offset(const rt::Fields& in) {
    const rt::Real w = in.length("width");
    const rt::Polygon surface({rt::Vec3(-w, 0, 1), rt::Vec3(w, 0, 1), rt::Vec3(w, 0, -1), rt::Vec3(-w, 0, -1)});
    const rt::Vec3 n = surface.normal(), light = in.vec3("light");
    const rt::Real error = in.length("error");  // how far below the surface rounding put p (drawn large)
    const rt::Offset offset{rt::OffsetMethod::normal, in.length("epsilon")};
    const rt::Real without = in.number("without_offset", rt::limits::coordinate);  // x of each case's hit
    const rt::Real with = in.number("with_offset", rt::limits::coordinate);
    if (light.y <= 0) in.fail("light", "must be above the surface (y > 0)");

    Canvas c;
    c.box({-double(w), -0.35 * double(light.y)}, {double(w), 0}, Ink::surface);
    c.circle(flat(light), 0.03 * double(light.y), Ink::light);
    c.label(flat(light), "light", Ink::light, 10, 4);
    for (const bool offset_it : {false, true}) {
        const rt::Vec3 exact(offset_it ? with : without, 0, 0), p = exact - error * n;
        const rt::SpawnedRay shadow =
            offset_it ? rt::spawn_ray({p, n, 0}, light - p, 1, offset) : rt::SpawnedRay{rt::Ray{p, light - p}, {0, 1}};
        rt::PolygonHit h;
        const bool blocked = rt::hit(surface, shadow.ray, shadow.interval, h);
        if (blocked) {
            const P2 q = flat(shadow.ray.at(h.t));
            c.line(flat(shadow.ray.origin), q, Ink::shadow);
            c.line(q, flat(light), Ink::guide, Stroke::dashed);
            c.dot(q, Ink::shadow);
            c.label(q, "hits its own surface: acne", Ink::shadow, 10, 14, Anchor::start, true);
        } else {
            c.arrow(flat(shadow.ray.origin), flat(light), Ink::shadow);
            c.label(0.5 * (flat(shadow.ray.origin) + flat(light)), "reaches the light", Ink::shadow, 10, 0,
                    Anchor::start, true);
        }
        if (offset_it) {
            c.arrow(flat(p), flat(shadow.ray.origin), Ink::normal);
            c.label(0.5 * (flat(p) + flat(shadow.ray.origin)), "ε n", Ink::normal, 8, -6);
        }
        c.dot(flat(exact), Ink::hit, true);
        if (!offset_it) c.label(flat(exact), "exact", Ink::hit, -10, 6, Anchor::end, true);
        c.dot(flat(p), Ink::hit);
        c.label(flat(p), "computed p", Ink::hit, 0, -24, Anchor::middle, true);
    }
    c.label({double(w), -0.35 * double(light.y)}, "surface", Ink::surface, -6, 8, Anchor::end, true);
    return c;
}

}  // namespace figures
