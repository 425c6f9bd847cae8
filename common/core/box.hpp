#pragma once
#include "core/interval.hpp"
#include "core/ray.hpp"

#include <cmath>

namespace rt {

// An axis-aligned bounding box: the `box` of the course's bounding-box() function.
struct Box {
    Vec3 min{kInfinity};
    Vec3 max{-kInfinity};

    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    void expand(const Vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void expand(const Box& b) {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
};

// Shrinks the interval to the part where the ray is inside the box; false if that part is
// empty. Errs towards keeping: the far end is padded by a few units in the last place
// (after Ize 2013), and a NaN from a ray lying in a slab's plane (0 * infinity) leaves that
// slab's bounds alone. Chapter 10 derives it (exercise 10.1 is the same test); the grid and
// the BSP clip rays to their box with it.
// inv_direction: 1 / ray.direction, when the caller has it already.
inline bool clip_to_box(const Box& box, const Ray& ray, const Vec3& inv_direction, Interval& interval) {
    Real lo = interval.min, hi = interval.max;
    for (int a = 0; a < 3; ++a) {
        const Real inv = inv_direction[a];
        Real t0 = (box.min[a] - ray.origin[a]) * inv, t1 = (box.max[a] - ray.origin[a]) * inv;
        // The sign of 1/d orders the planes (-0 gives -inf); comparing t0 with t1 would not
        // when one of them is NaN.
        if (inv < 0) std::swap(t0, t1);
        if (t0 > lo) lo = t0;
        if (t1 < hi) hi = t1;
    }
    hi = widen_far(hi);
    if (!(lo <= hi)) return false;
    interval = Interval{lo, hi};
    return true;
}

inline bool clip_to_box(const Box& box, const Ray& ray, Interval& interval) {
    return clip_to_box(box, ray, Real(1) / ray.direction, interval);
}

// Might the ray meet the box for some t in the interval? A cull in front of meshes and
// instances, so that a ray that passes far from them costs one test.
inline bool might_hit(const Box& box, const Ray& ray, const Vec3& inv_direction, Interval interval) {
    return clip_to_box(box, ray, inv_direction, interval);
}
inline bool might_hit(const Box& box, const Ray& ray, Interval interval) {
    return clip_to_box(box, ray, interval);
}

}  // namespace rt
