// Book §5.3-5.4: the vectors of shading at a hit. A camera ray finds the sphere (its hit
// record gives p and the normal n); l points to the light, v back to the eye, h halfway
// between them (Blinn-Phong's half vector, as blinn_phong_highlight forms it) and r is l
// mirrored about n by reflect (exercise 7.1): Phong's highlight compares r with v,
// Blinn-Phong's compares h with n.
#include "geometry/shape.hpp"
#include "kinds.hpp"
#include "shading/optics.hpp"

namespace figures {

Canvas shading_vectors(const rt::Fields& in) {
    const rt::Sphere sphere(in.vec3("center"), in.length("radius"));
    const rt::Vec3 eye = in.vec3("eye"), light = in.vec3("light");
    const rt::Ray ray{eye, in.direction("aim")};
    const double len = double(in.length("arrow"));  // how long the unit vectors are drawn

    rt::HitRecord rec;
    if (!rt::hit_record(sphere, ray, rt::Interval{0, rt::kInfinity}, rt::SurfaceRef{}, rec))
        in.fail("aim", "the ray from the eye misses the sphere");
    const rt::Vec3 n = rec.normal, l = rt::unit_vector(light - rec.p), v = rt::unit_vector(eye - rec.p);
    const rt::Vec3 h = glm::normalize(l + v);
    const rt::Vec3 r = rt::reflect(-l, n);

    Canvas c;
    c.circle(flat(sphere.center), double(sphere.radius), Ink::surface);
    const P2 p = flat(rec.p);
    c.line(flat(eye), p, Ink::camera, Stroke::thin);
    c.line(p, flat(light), Ink::shadow, Stroke::thin);
    c.dot(flat(eye), Ink::camera);
    c.label(flat(eye), "eye", Ink::camera, -8, 6, Anchor::end);
    c.circle(flat(light), 0.08 * double(sphere.radius), Ink::light);
    c.label(flat(light), "light", Ink::light, 10, 6);
    const auto vec = [&](const rt::Vec3& d, Ink ink, const char* name) {
        c.arrow(p, p + len * flat(d), ink);
        c.label(p + len * flat(d), name, ink, d.x < 0 ? -6 : 6, 4, d.x < 0 ? Anchor::end : Anchor::start);
    };
    vec(n, Ink::normal, "n");
    vec(l, Ink::shadow, "l");
    vec(v, Ink::camera, "v");
    vec(h, Ink::axis, "h");
    vec(r, Ink::reflected, "r");
    c.dot(p, Ink::hit);
    c.label(flat(sphere.center - rt::Vec3(0, sphere.radius, 0)),
            "angle(n, h) = " + number(degrees_between(n, h), 3) +
                "°, angle(r, v) = " + number(degrees_between(r, v), 3) + "°",
            Ink::axis, 0, -26, Anchor::middle, true);
    return c;
}

}  // namespace figures
