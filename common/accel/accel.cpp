#include "accel/accel.hpp"

#include <chrono>

namespace rt {

bool BruteForce::hit(const SurfaceList& surfaces, const Ray& ray, Interval interval, HitRecord& rec) const {
    HitRecord best = no_hit_before(interval.max);
    bool found = false;
    for (const Primitive& p : primitives_)
        if (hit_closer(surfaces, p, ray, Interval{interval.min, best.t}, best)) found = true;
    traversal_tally.items += primitives_.size();
    if (found) rec = best;
    return found;
}

bool BruteForce::occluded(const SurfaceList& surfaces, const Ray& ray, Interval interval) const {
    for (std::size_t k = 0; k < primitives_.size(); ++k)
        if (rt::occluded(surfaces, primitives_[k], ray, interval)) {
            traversal_tally.items += k + 1;
            return true;
        }
    traversal_tally.items += primitives_.size();
    return false;
}

namespace {

std::variant<BruteForce, Bvh, Grid, Bsp, TwoLevelBvh> make(const SurfaceList& surfaces, AccelKind kind) {
    switch (kind) {
        case AccelKind::bvh_sort:
            return Bvh(surfaces, BvhBuild::sorted);
        case AccelKind::bvh_midpoint:
            return Bvh(surfaces, BvhBuild::midpoint);
        case AccelKind::bvh_sah:
            return Bvh(surfaces, BvhBuild::sah);
        case AccelKind::grid:
            return Grid(surfaces);
        case AccelKind::bsp_midpoint:
            return Bsp(surfaces, BspBuild::midpoint);
        case AccelKind::bsp:
            return Bsp(surfaces, BspBuild::sah);
        case AccelKind::fast:
            return TwoLevelBvh(surfaces);
        case AccelKind::none:
            break;
    }
    return BruteForce(surfaces);
}

}  // namespace

Accel::Accel(const SurfaceList& surfaces, AccelKind kind)
    : impl_([&] {
          const auto start = std::chrono::steady_clock::now();
          auto impl = make(surfaces, kind);
          info_.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          return impl;
      }()) {
    info_.kind = kind;
    // The two trees built from primitives answer the same four questions.
    const auto tree = [&](const auto& t) {
        info_.primitives = t.primitive_count();
        info_.nodes = t.node_count();
        info_.bytes = t.memory_bytes();
        info_.depth = t.depth();
    };
    match(
        impl_, [&](const BruteForce& b) { info_.primitives = b.primitive_count(); }, [&](const Bvh& b) { tree(b); },
        [&](const Bsp& b) { tree(b); },
        [&](const Grid& g) {
            info_.primitives = g.primitive_count();
            info_.nodes = g.cell_count();
            info_.bytes = g.memory_bytes();
        },
        [&](const TwoLevelBvh& f) {
            info_.primitives = primitives_of(surfaces).size();
            info_.nodes = f.node_count(surfaces);
            info_.bytes = f.memory_bytes(surfaces);
            info_.depth = f.depth();
        });
}

}  // namespace rt
