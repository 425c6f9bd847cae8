#pragma once
// The scene's search structure, chosen by --accel or a scene file's "accel" (book §10.6):
//   none          every primitive, one after the other (brute force: the reference)
//   bvh-sort      the course's BVH, sorted build (exercises 10.1, 10.2, 10.4)
//   bvh-midpoint  the course's BVH, midpoint build (exercises 10.1, 10.3, 10.4)
//   bvh-sah       the course's BVH over a surface-area-heuristic tree (exercises 10.1, 10.4)
//   grid          the uniform grid (exercises 11.1, 11.2)
//   bsp-midpoint  the course's BSP tree, cyclic midpoint build (exercises 12.1, 12.2)
//   bsp           the course's BSP tree, surface-area-heuristic build (exercise 12.1)
//   fast          the two-level flat BVH (the default; library code only)
// All return the same closest hit (t, surface and primitive) and the same any-hit answer.
#include "accel/bsp.hpp"
#include "accel/course_bvh.hpp"
#include "accel/grid.hpp"
#include "accel/primitive.hpp"
#include "accel/two_level_bvh.hpp"
#include "core/dispatch.hpp"
#include "core/names.hpp"

#include <span>
#include <variant>

namespace rt {

enum class AccelKind { none, bvh_sort, bvh_midpoint, bvh_sah, grid, bsp_midpoint, bsp, fast };
inline constexpr auto kAccelNames =
    names_of<AccelKind>({"none", "bvh-sort", "bvh-midpoint", "bvh-sah", "grid", "bsp-midpoint", "bsp", "fast"});
inline constexpr auto kAccelKinds = kAccelNames.values();

// Brute force over primitives: what every structure must agree with.
class BruteForce {
public:
    explicit BruteForce(const SurfaceList& surfaces) : primitives_(primitives_of(surfaces)) {}
    bool hit(const SurfaceList& surfaces, const Ray& ray, Interval interval, HitRecord& rec) const;
    bool occluded(const SurfaceList& surfaces, const Ray& ray, Interval interval) const;
    std::size_t primitive_count() const { return primitives_.size(); }

private:
    std::vector<Primitive> primitives_;
};

// What --stats says about a structure.
struct AccelInfo {
    AccelKind kind = AccelKind::none;
    double build_seconds = 0;
    std::size_t primitives = 0;  // what the structure sorts (a mesh: its triangles)
    std::size_t nodes = 0;
    std::size_t bytes = 0;
    int depth = 0;
};

class Accel {
public:
    // Builds the structure over the surfaces. The queries take the same list (or an equal
    // copy: a copied Scene) again, so nothing here points into a Scene that may move.
    Accel(const SurfaceList& surfaces, AccelKind kind);

    bool hit(const SurfaceList& surfaces, const Ray& ray, Interval interval, HitRecord& rec) const {
        return dispatch(impl_, [&](const auto& a) { return a.hit(surfaces, ray, interval, rec); });
    }
    bool occluded(const SurfaceList& surfaces, const Ray& ray, Interval interval) const {
        return dispatch(impl_, [&](const auto& a) { return a.occluded(surfaces, ray, interval); });
    }
    // The closest hits of rays from one point (a pinhole camera's): recs[k], and bit k of the
    // answer, for ray k, each what hit() gives it. The fast path searches them as a packet
    // (core/wide_packet.hpp); the course's structures, one after another.
    unsigned hit_packet(const SurfaceList& surfaces, std::span<const Ray> rays, Interval interval,
                        HitRecord* recs) const {
        return dispatch(impl_, [&](const auto& a) {
            if constexpr (requires { a.hit_packet(surfaces, rays, interval, recs); }) {
                return a.hit_packet(surfaces, rays, interval, recs);
            } else {
                return one_by_one(rays.size(),
                                  [&](std::size_t k) { return a.hit(surfaces, rays[k], interval, recs[k]); });
            }
        });
    }
    const AccelInfo& info() const { return info_; }

private:
    AccelInfo info_;  // before impl_: building impl_ records its time here
    std::variant<BruteForce, Bvh, Grid, Bsp, TwoLevelBvh> impl_;
};

}  // namespace rt
