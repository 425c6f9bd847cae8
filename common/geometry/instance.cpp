#include "geometry/instance.hpp"

#include "geometry/shape.hpp"

#include <cmath>
#include <limits>

namespace rt {

Instance::Instance(std::shared_ptr<const Shape> base, const Affine& to_world)
    : base_(std::move(base)), to_world_(to_world), to_object_(inverse(to_world, "instance")) {
    box_ = transform_box(to_world_, rt::bounding_box(*base_));
}

namespace {

// How far each coordinate of a.point(p) = M p + t may lie from the exact value: four
// roundings (a product and three sums), within gamma_4 (pbrt §3.9), under 2 eps, of the
// sum of the terms' magnitudes; 3 eps leaves a margin.
Real point_rounding(const Affine& a, const Vec3& p) {
    const Vec3 terms = glm::abs(a.m[0]) * std::abs(p.x) + glm::abs(a.m[1]) * std::abs(p.y) +
                       glm::abs(a.m[2]) * std::abs(p.z) + glm::abs(a.t);
    return 3 * std::numeric_limits<Real>::epsilon() * glm::length(terms);
}

}  // namespace

// The base shape's bound (object space, along its normal) seen in the world, with the
// transform's own rounding. A world distance w off the surface along the world normal n is
// w / |M^T n| off it in object space (the tangent plane's preimage has normal M^T n), so the
// object's bound stretches by |M^T n|, at most M's largest stretch. The spawned ray goes
// back through to_object, whose rounding of its origin is an object-space error too; and
// rec.p's own rounding, in world space, adds as it is.
Real world_error(const Instance& instance, const HitRecord& local, const HitRecord& world) {
    const Real stretch = glm::length(glm::transpose(instance.to_world().m) * world.normal);
    const Real object = local.error + point_rounding(instance.to_object(), world.p);
    return stretch * object + point_rounding(instance.to_world(), local.p);
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
    rec.error = world_error(instance, h.local, rec);
    rec.surface = who.surface;
    rec.material = h.local.material != kNone ? h.local.material : who.material;
    return rec;
}

}  // namespace rt
