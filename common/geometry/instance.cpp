#include "geometry/instance.hpp"

#include "geometry/shape.hpp"

namespace rt {

Instance::Instance(std::shared_ptr<const Shape> base, const Affine& to_world)
    : base_(std::move(base)), to_world_(to_world), to_object_(inverse(to_world, "instance")) {
    box_ = transform_box(to_world_, rt::bounding_box(*base_));
}

bool hit(const Instance& instance, const Ray& ray, Interval interval, InstanceHit& result) {
    if (!might_hit(instance.box(), ray, interval)) return false;
    // The owner is stamped by record() below, on the world-space record. The material is
    // left unset so that one a CSG operand chose (geometry/csg.hpp) can be told apart.
    return hit_record(instance.base(), object_ray(instance.to_object(), ray), interval, SurfaceRef{kNone, kNone},
                      result.local);
}

bool occluded(const Instance& instance, const Ray& ray, Interval interval) {
    if (!might_hit(instance.box(), ray, interval)) return false;
    return occluded(instance.base(), object_ray(instance.to_object(), ray), interval);
}

HitRecord record(const Instance& instance, const Ray&, const InstanceHit& h, SurfaceRef who) {
    HitRecord rec = h.local;  // t, triangle and barycentrics carry over unchanged
    rec.p = instance.to_world().point(h.local.p);
    rec.normal = world_normal(instance.to_object(), h.local.normal);
    rec.shading_normal = world_normal(instance.to_object(), h.local.shading_normal);
    rec.surface = who.surface;
    rec.material = h.local.material != kNone ? h.local.material : who.material;
    return rec;
}

}  // namespace rt
