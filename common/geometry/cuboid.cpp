#include "geometry/cuboid.hpp"

#include <cmath>
#include <stdexcept>

namespace rt {

Cuboid::Cuboid(const Vec3& lo, const Vec3& hi) : min(lo), max(hi) {
    for (int a = 0; a < 3; ++a) {
        if (!std::isfinite(lo[a]) || !std::isfinite(hi[a])) throw std::invalid_argument("box: corners must be finite");
        if (!(lo[a] < hi[a])) throw std::invalid_argument("box: min must be below max on every axis");
    }
}

bool cuboid_crossings(const Cuboid& box, const Ray& ray, CuboidHit& enter, CuboidHit& leave) {
    enter = CuboidHit{-kInfinity, -1, 0};
    leave = CuboidHit{kInfinity, -1, 0};
    for (int a = 0; a < 3; ++a) {
        const Real d = ray.direction[a];
        if (d == 0) {
            // Parallel to the slab: inside it for every t, or never. (1/d would make
            // 0 * inf = NaN for an origin on a face.)
            if (ray.origin[a] < box.min[a] || ray.origin[a] > box.max[a]) return false;
            continue;
        }
        const Real inv = Real(1) / d;
        Real t0 = (box.min[a] - ray.origin[a]) * inv, t1 = (box.max[a] - ray.origin[a]) * inv;
        int s0 = -1, s1 = +1;
        if (inv < 0) std::swap(t0, t1), std::swap(s0, s1);
        if (t0 > enter.t) enter = CuboidHit{t0, a, s0};
        if (t1 < leave.t) leave = CuboidHit{t1, a, s1};
    }
    return enter.axis >= 0 && leave.axis >= 0 && enter.t <= leave.t;
}

bool hit(const Cuboid& box, const Ray& ray, Interval interval, CuboidHit& result) {
    CuboidHit enter, leave;
    if (!cuboid_crossings(box, ray, enter, leave)) return false;
    if (interval.contains(enter.t)) {
        result = enter;
        return true;
    }
    if (interval.contains(leave.t)) {
        result = leave;
        return true;
    }
    return false;
}

HitRecord record(const Cuboid& box, const Ray& ray, const CuboidHit& h, SurfaceRef who) {
    HitRecord rec;
    rec.t = h.t;
    rec.p = ray.at(h.t);
    // The point lies on the face's plane: say so exactly, so the offset starts from it.
    rec.p[h.axis] = h.side > 0 ? box.max[h.axis] : box.min[h.axis];
    rec.normal = Vec3(0);
    rec.normal[h.axis] = Real(h.side);
    rec.shading_normal = rec.normal;
    rec.surface = who.surface;
    rec.material = who.material;
    return rec;
}

}  // namespace rt
