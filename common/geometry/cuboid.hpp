#pragma once
// An axis-aligned box as a solid shape (book §13): the simplest closed shape after the
// sphere, and the body of chapter 13's die. A rotated or stretched one is an instance.
#include "core/box.hpp"
#include "core/interval.hpp"
#include "core/ray.hpp"
#include "geometry/hit_record.hpp"

namespace rt {

// Where a ray crosses a cuboid's surface, and through which face: axis 0-2, and whether it
// is the face at the box's max (+1) or min (-1) on that axis.
struct CuboidHit {
    Real t;
    int axis;
    int side;
};

struct Cuboid {
    using Hit = CuboidHit;

    Vec3 min, max;

    // Throws std::invalid_argument unless the corners are finite and min < max on every axis.
    Cuboid(const Vec3& min, const Vec3& max);
};

// Where the ray's line enters and leaves the cuboid (the slab test on the whole line);
// false if it misses. `enter.t <= leave.t`.
bool cuboid_crossings(const Cuboid& box, const Ray& ray, CuboidHit& enter, CuboidHit& leave);

// The first crossing in the interval.
bool hit(const Cuboid& box, const Ray& ray, Interval interval, CuboidHit& result);
HitRecord record(const Cuboid& box, const Ray& ray, const CuboidHit& h, SurfaceRef who = {});
inline Box bounding_box(const Cuboid& box) {
    return Box{box.min, box.max};
}

}  // namespace rt
