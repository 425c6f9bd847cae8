#pragma once
// Instancing (book §9, course §9.8): a shape seen through an affine transform. The ray is
// taken into the shape's own space instead of the shape into the world, so one mesh can
// appear many times while its triangles are stored once. instance.cpp holds the queries;
// object_ray, world_normal and transform_box are the chapter 09 exercises.
#include "core/box.hpp"
#include "core/interval.hpp"
#include "core/ray.hpp"
#include "core/transform.hpp"
#include "geometry/hit_record.hpp"

#include <memory>

namespace rt {

struct Shape;  // geometry/shape.hpp: an instance may hold any shape, another instance too

// The three are graded within rounding, never by their bits, so that any arrangement of the
// products passes (columns or rows, fma, the translation first or last): each result within a
// few machine epsilons of the size of what it sums (|M^-1| |e| + |t| for a point, |M^-1| |d|
// for a direction), exactly only where every number is exact.

// Exercise 9.1: the ray in object space, M^-1 e + t M^-1 d. The direction is not
// renormalised, so a hit's t is the same in both spaces; it is M^-1 d, which the translation
// never touches: an instance 10^6 from the origin leaves it all its digits (8 epsilons).
// The ray keeps its time.
Ray object_ray(const Affine& to_object, const Ray& ray);

// Exercise 9.2: a normal of the object brought into the world: (M^-1)^T n, made unit length
// again. Normals transform by the inverse transpose so they stay perpendicular to the
// transformed surface (the course's §5.2.2), and an outward normal stays outward whatever the
// sign of det M: a mirror reverses a mesh's winding, not its normals. Within 64 epsilons of
// the unit vector, under mirrors and scales of 1e-4 too.
Vec3 world_normal(const Affine& to_object, const Vec3& n);

// Exercise 9.3: a box around the transformed box: the box of its eight transformed corners,
// each face within 8 epsilons of the size of what it sums (|t| + |M| |corner|). Arvo's way (the
// centre transformed, the half-extent by |M|) passes as well as the corners'.
Box transform_box(const Affine& to_world, const Box& box);

// What an instance's test finds: the base shape's whole record, in object space.
struct InstanceHit {
    HitRecord local;
};

class Instance {
public:
    using Hit = InstanceHit;

    // Throws std::invalid_argument for a singular transform.
    Instance(std::shared_ptr<const Shape> base, const Affine& to_world);

    const Shape& base() const { return *base_; }
    const std::shared_ptr<const Shape>& shared_base() const { return base_; }
    const Affine& to_world() const { return to_world_; }
    const Affine& to_object() const { return to_object_; }
    const Box& box() const { return box_; }

private:
    std::shared_ptr<const Shape> base_;
    Affine to_world_, to_object_;
    Box box_;
};

// How far the world record's p may lie off the instance's surface (HitRecord::error): the
// base shape's bound `local.error`, stretched by the transform along the normal, plus the
// rounding of the transform both ways (the hit point out, a spawned ray's origin back).
Real world_error(const Instance& instance, const HitRecord& local, const HitRecord& world);

bool hit(const Instance& instance, const Ray& ray, Interval interval, InstanceHit& result);
bool occluded(const Instance& instance, const Ray& ray, Interval interval);
HitRecord record(const Instance& instance, const Ray& ray, const InstanceHit& h, SurfaceRef who = {});
inline Box bounding_box(const Instance& instance) {
    return instance.box();
}

}  // namespace rt
