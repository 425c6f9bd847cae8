// Book §9.2-9.3: instancing. The world sees a sphere stretched and turned by M; the library
// keeps the unit sphere and takes the ray to it instead: object_ray (exercise 9.1) applies
// M^-1 to the ray, the unit sphere's own test finds the hit, and world_normal (exercise
// 9.2) brings its normal back by the inverse transpose. Transforming the normal by M itself,
// as a direction, would tilt it off the surface: drawn dashed for comparison.
#include "geometry/shape.hpp"
#include "kinds.hpp"

#include <memory>

namespace figures {

Canvas instancing(const rt::Fields& in) {
    const rt::Affine to_world =
        rt::Affine::scale(in.vec3("scale"))
            .then(rt::Affine::rotate(rt::Vec3(0, 0, 1), in.number("degrees", rt::limits::angle)))
            .then(rt::Affine::translate(in.vec3("translate")));
    const rt::Instance instance(std::make_shared<const rt::Shape>(rt::Sphere(rt::Vec3(0), 1)), to_world);
    const rt::Ray ray{in.vec3("origin"), in.direction("direction")};
    const rt::Vec3 shift = in.vec3("object_panel");  // where the object-space panel is drawn, beside the world
    const double len = double(in.length("arrow"));

    rt::InstanceHit h;
    if (!rt::hit(instance, ray, rt::Interval{0, rt::kInfinity}, h)) in.fail("direction", "the ray misses the instance");
    const rt::HitRecord world = rt::record(instance, ray, h);
    const rt::Ray local = rt::object_ray(instance.to_object(), ray);
    const rt::Vec3 naive = rt::unit_vector(to_world.vector(h.local.normal));

    Canvas c;
    std::vector<P2> ellipse, circle;
    for (int k = 0; k < 96; ++k) {
        const double a = 2 * M_PI * k / 96;
        const rt::Vec3 q(rt::Real(std::cos(a)), rt::Real(std::sin(a)), 0);
        circle.push_back(flat(q + shift));
        ellipse.push_back(flat(to_world.point(q)));
    }
    // The world.
    c.polygon(ellipse, Ink::surface);
    c.arrow(flat(ray.origin), flat(world.p), Ink::camera);
    c.dot(flat(world.p), Ink::hit);
    c.arrow(flat(world.p), flat(world.p) + len * flat(world.normal), Ink::normal);
    c.label(flat(world.p) + len * flat(world.normal), "(M⁻¹)ᵀ n", Ink::normal, -6, 6, Anchor::end);
    c.arrow(flat(world.p), flat(world.p) + len * flat(naive), Ink::guide, Stroke::dashed);
    c.label(flat(world.p) + len * flat(naive), "M n: not normal", Ink::guide, 6, 4, Anchor::start, true);
    c.label(flat(to_world.point(rt::Vec3(0, -1, 0))), "world: the unit sphere by M", Ink::axis, 0, -30, Anchor::middle,
            true);
    // Object space: the same t on the ray M^-1 e + t M^-1 d.
    c.polygon(circle, Ink::surface);
    c.arrow(flat(local.origin + shift), flat(local.at(world.t) + shift), Ink::camera);
    c.dot(flat(local.at(world.t) + shift), Ink::hit);
    c.arrow(flat(h.local.p + shift), flat(h.local.p + shift) + len * flat(h.local.normal), Ink::normal);
    c.label(flat(h.local.p + shift) + len * flat(h.local.normal), "n", Ink::normal, 6, 4);
    c.label(flat(shift - rt::Vec3(0, 1, 0)), "object space: the ray by M⁻¹", Ink::axis, 0, -30, Anchor::middle, true);
    c.label(flat(local.at(world.t) + shift), "t = " + number(double(world.t)), Ink::hit, 8, -20, Anchor::start, true);
    c.label(flat(world.p), "t = " + number(double(world.t)), Ink::hit, 8, -20, Anchor::start, true);
    return c;
}

}  // namespace figures
