#include "accel/two_level_bvh.hpp"

#include "accel/primitive.hpp"

#include <bit>
#include <set>

namespace rt {

TwoLevelBvh::TwoLevelBvh(const SurfaceList& surfaces) {
    std::vector<Box> boxes;
    boxes.reserve(surfaces.size());
    for (const Surface& s : surfaces.surfaces()) boxes.push_back(s.bounding_box());
    const FlatBvh bvh = build_bvh(boxes, 2);
    wide_ = collapse<kWidth>(bvh);
    items_ = bvh.items;
    depth_ = bvh.depth;
    spheres_.reserve(items_.size());
    for (std::uint32_t item : items_) {
        const Sphere* sphere = std::get_if<Sphere>(&surfaces[SurfaceId(item)].shape);
        spheres_.push_back(sphere && !sphere->moves() ? std::optional<Sphere>(*sphere) : std::nullopt);
    }
}

// A surface's id is its place in the list (SurfaceList::add), so a slot's item number is the
// id a still sphere's hit carries, and the sphere's own surface is read only for the record
// of the one that wins.
//
// A still sphere's hit is kept as its t and surface only (all `closer` ranks by), and its
// whole record (point, normal, error) made once, for the sphere that wins: a ray through a
// row of spheres meets several on its way to the nearest, and the record is what costs.
// best_sphere is that sphere's slot, or kNone when `best` is another item's whole record.
[[gnu::always_inline]] inline bool TwoLevelBvh::leaf_closest(const SurfaceList& surfaces, const Ray& ray,
                                                             std::uint32_t first, std::uint32_t count, Interval& iv,
                                                             HitRecord& best, std::uint32_t& best_sphere) const {
    bool nearer = false;
    for (std::uint32_t k = first; k < first + count; ++k) {
        if (const std::optional<Sphere>& sphere = spheres_[k]) {
            // hit_closer's test (a few ulps past the far end), without the record.
            SphereHit h;
            if (!rt::hit(*sphere, ray, Interval{iv.min, widen_far(iv.max)}, h) ||
                !closer(h.t, SurfaceId(items_[k]), kNone, best))
                continue;
            best.t = h.t;
            best.surface = SurfaceId(items_[k]);
            best.primitive = kNone;
            best_sphere = k;
        } else {
            if (!hit_closer(surfaces[SurfaceId(items_[k])], ray, iv, best)) continue;
            best_sphere = kNone;
        }
        iv.max = best.t;
        nearer = true;
    }
    return nearer;
}

void TwoLevelBvh::record_closest(const SurfaceList& surfaces, const Ray& ray, const HitRecord& best,
                                 std::uint32_t best_sphere, HitRecord& rec) const {
    if (best_sphere != kNone) {
        const Surface& surface = surfaces[SurfaceId(items_[best_sphere])];
        rec = record(*spheres_[best_sphere], ray, SphereHit{best.t}, SurfaceRef{surface.id, surface.material});
    } else {
        rec = best;
    }
}

bool TwoLevelBvh::hit_upper(const SurfaceList& surfaces, const Ray& ray, Interval interval, HitRecord& rec) const {
    HitRecord best = no_hit_before(interval.max);
    std::uint32_t best_sphere = kNone;
    const bool found = closest_hit(
        wide_, WideRay<kWidth>(ray), interval,
        [&](std::uint32_t first, std::uint32_t count, Interval& iv) {
            return leaf_closest(surfaces, ray, first, count, iv, best, best_sphere);
        },
        [](std::uint32_t) {});
    if (found) record_closest(surfaces, ray, best, best_sphere, rec);
    return found;
}

unsigned TwoLevelBvh::hit_packet(const SurfaceList& surfaces, std::span<const Ray> rays, Interval interval,
                                 HitRecord* recs) const {
    WidePacket packet;
    if (!make_packet(rays, interval, packet))
        return one_by_one(rays.size(), [&](std::size_t k) { return hit(surfaces, rays[k], interval, recs[k]); });
    if (surfaces.size() == 1) return surfaces[SurfaceId(0)].hit_packet(packet, rays, interval, recs);
    // Each ray's search as hit_upper keeps it.
    struct Search {
        Interval iv;
        HitRecord best;
        std::uint32_t best_sphere;
    };
    Search search[kPacketRays];
    for (std::size_t k = 0; k < rays.size(); ++k) search[k] = {interval, no_hit_before(interval.max), kNone};
    unsigned found = 0;
    closest_hits(
        wide_, packet,
        [&](std::uint32_t first, std::uint32_t count, unsigned which) {
            bool narrowed = false;
            for (; which != 0; which &= which - 1) {
                const int k = std::countr_zero(which);
                Search& s = search[k];
                if (leaf_closest(surfaces, rays[std::size_t(k)], first, count, s.iv, s.best, s.best_sphere)) {
                    found |= 1u << k;
                    packet.narrow(k, s.iv.max);
                    narrowed = true;
                }
            }
            return narrowed;
        },
        [](std::uint32_t) {});
    for (unsigned m = found; m != 0; m &= m - 1) {
        const int k = std::countr_zero(m);
        record_closest(surfaces, rays[std::size_t(k)], search[k].best, search[k].best_sphere, recs[k]);
    }
    return found;
}

bool TwoLevelBvh::occluded_upper(const SurfaceList& surfaces, const Ray& ray, Interval interval) const {
    return any_hit(
        wide_, WideRay<kWidth>(ray), interval,
        [&](std::uint32_t first, std::uint32_t count, Interval& iv) {
            for (std::uint32_t k = first; k < first + count; ++k) {
                if (const std::optional<Sphere>& sphere = spheres_[k]) {
                    SphereHit h;
                    if (rt::hit(*sphere, ray, iv, h)) return true;
                } else if (surfaces[SurfaceId(items_[k])].occluded(ray, iv)) {
                    return true;
                }
            }
            return false;
        },
        [](std::uint32_t) {});
}

namespace {

// Every distinct mesh's BVH below the surfaces, in instances and CSG objects too, once each.
template <class F>
void for_each_mesh_accel(const SurfaceList& surfaces, F&& f) {
    std::set<const MeshAccel*> seen;
    const auto visit = [&](const Shape& shape, const auto& self) -> void {
        match(
            shape,
            [&](const Mesh& mesh) {
                if (seen.insert(&mesh.accel()).second) f(mesh.accel());
            },
            [&](const Instance& instance) { self(instance.base(), self); },
            [&](const Csg& csg) {
                self(*csg.left().shape, self);
                self(*csg.right().shape, self);
            },
            [](const Sphere&) {}, [](const Triangle&) {}, [](const Polygon&) {}, [](const Cuboid&) {});
    };
    for (const Surface& s : surfaces.surfaces()) visit(s.shape, visit);
}

}  // namespace

std::size_t TwoLevelBvh::memory_bytes(const SurfaceList& surfaces) const {
    std::size_t bytes =
        wide_.memory_bytes() + items_.size() * sizeof(std::uint32_t) + spheres_.size() * sizeof(spheres_[0]);
    for_each_mesh_accel(surfaces, [&](const MeshAccel& a) { bytes += a.memory_bytes(); });
    return bytes;
}

std::size_t TwoLevelBvh::node_count(const SurfaceList& surfaces) const {
    std::size_t nodes = wide_.nodes.size();
    for_each_mesh_accel(surfaces, [&](const MeshAccel& a) { nodes += a.wide.nodes.size(); });
    return nodes;
}

}  // namespace rt
