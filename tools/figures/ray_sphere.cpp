// Book §2: rays meeting a sphere. Both roots come from sphere_roots (exercise 2.2), the hit
// the renderer takes from hit(Sphere) (exercise 2.3) and its normal from the sphere's hit
// record; a ray that misses shows its closest approach to the centre, farther than R.
#include "geometry/sphere.hpp"
#include "kinds.hpp"

namespace figures {

Canvas ray_sphere(const rt::Fields& in) {
    const rt::Sphere sphere(in.vec3("center"), in.length("radius"));
    Canvas c;
    const P2 center = flat(sphere.center);
    c.circle(center, double(sphere.radius), Ink::surface);
    c.dot(center, Ink::axis, true);
    c.label(center, "c", Ink::axis, 8, -18);
    for (const rt::Fields& r : in.objects("rays")) {
        const rt::Ray ray{r.vec3("origin"), r.direction("direction")};
        const double reach = double(r.length("length", 4));  // how far to draw a ray that misses
        r.done();
        const P2 e = flat(ray.origin);
        c.dot(e, Ink::camera);
        c.label(e, "e", Ink::camera, -8, 8, Anchor::end);
        rt::Real t_near, t_far;
        if (rt::sphere_roots(ray, sphere.center, sphere.radius, t_near, t_far)) {
            rt::SphereHit h;
            if (!rt::hit(sphere, ray, rt::Interval{0, rt::kInfinity}, h))
                r.fail("origin", "the line meets the sphere behind the eye");
            const rt::HitRecord rec = rt::record(sphere, ray, h);
            const P2 p0 = flat(ray.at(t_near)), p1 = flat(ray.at(t_far));
            c.arrow(e, p0, Ink::camera);
            c.line(p0, p1, Ink::camera, Stroke::dashed);  // the line goes on through the sphere
            c.dot(p0, Ink::hit);
            c.dot(p1, Ink::hit, true);
            c.label(p0, "t₀ = " + number(double(t_near)), Ink::hit, -10, -22, Anchor::end);
            c.label(p1, "t₁ = " + number(double(t_far)), Ink::hit, 8, -16);
            const P2 p = flat(rec.p);
            c.arrow(p, p + 0.55 * double(sphere.radius) * flat(rec.normal), Ink::normal);
            c.label(p + 0.55 * double(sphere.radius) * flat(rec.normal), "n", Ink::normal, 4, 4);
        } else {
            // Where the line comes closest to the centre: the foot of the perpendicular.
            const rt::Vec3 f = ray.origin - sphere.center;
            const rt::Real t_closest = -glm::dot(f, ray.direction) / glm::dot(ray.direction, ray.direction);
            const rt::Vec3 foot = ray.at(t_closest);
            const P2 end = flat(ray.origin + rt::Real(reach) * rt::unit_vector(ray.direction));
            c.arrow(e, end, Ink::camera);
            c.line(center, flat(foot), Ink::guide, Stroke::dashed);
            c.dot(flat(foot), Ink::guide);
            c.label(flat(foot), "h = " + number(double(glm::length(foot - sphere.center))) + " > R", Ink::axis, 8, 6);
        }
    }
    c.line(center, center - P2{double(sphere.radius), 0}, Ink::surface, Stroke::thin);
    c.label(center - P2{0.5 * double(sphere.radius), 0}, "R = " + number(double(sphere.radius)), Ink::surface, 0, 8,
            Anchor::middle);
    return c;
}

}  // namespace figures
