#pragma once
// The renderer's default search (book §10.5): two levels of BVH. The upper one is built over
// the scene's surfaces with the SAH of core/flat_bvh.hpp and collapsed to the eight-wide form
// the meshes search in (core/wide_bvh.hpp), so a ray tests eight surfaces' boxes at once in
// float, conservatively, and only the leaves decide in Real. A mesh surface is one item there
// and searches its triangles through its own BVH (geometry/mesh.hpp), which the mesh's copies
// and instances share. Returns exactly the hits of the brute-force search.
#include "accel/surface_list.hpp"
#include "core/wide_bvh.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace rt {

class TwoLevelBvh {
public:
    // Children per node of the upper level: one AVX register of boxes, as a mesh's.
    static constexpr int kWidth = 8;

    explicit TwoLevelBvh(const SurfaceList& surfaces);

    // A scene of one surface (a mesh alone) needs no upper level: its own search is the
    // whole. Decided here, inline, so that such a ray does not pay for the upper search's
    // prologue (its saved registers cost ~25 instructions per camera ray on the bunny).
    bool hit(const SurfaceList& surfaces, const Ray& ray, Interval interval, HitRecord& rec) const {
        if (surfaces.size() == 1) return surfaces[SurfaceId(0)].hit(ray, interval, rec);
        return hit_upper(surfaces, ray, interval, rec);
    }
    bool occluded(const SurfaceList& surfaces, const Ray& ray, Interval interval) const {
        if (surfaces.size() == 1) return surfaces[SurfaceId(0)].occluded(ray, interval);
        return occluded_upper(surfaces, ray, interval);
    }

    // The closest hits of rays from one point, a pinhole camera's (core/wide_packet.hpp):
    // recs[k], and bit k of the answer, for ray k, each what hit() gives it. The rays are
    // searched as one packet where they can be, else one at a time.
    unsigned hit_packet(const SurfaceList& surfaces, std::span<const Ray> rays, Interval interval,
                        HitRecord* recs) const;

    // The depth of the binary tree the upper level was collapsed from (what --stats reports).
    int depth() const { return depth_; }
    // The upper level plus every distinct mesh's BVH, counted once however often it is used.
    std::size_t memory_bytes(const SurfaceList& surfaces) const;
    std::size_t node_count(const SurfaceList& surfaces) const;

private:
    bool hit_upper(const SurfaceList& surfaces, const Ray& ray, Interval interval, HitRecord& rec) const;
    bool occluded_upper(const SurfaceList& surfaces, const Ray& ray, Interval interval) const;
    // One ray's closest-hit search among the upper level's items, leaf by leaf (hit_upper's
    // and hit_packet's): `best` and `best_sphere` are its state (see hit_upper).
    bool leaf_closest(const SurfaceList& surfaces, const Ray& ray, std::uint32_t first, std::uint32_t count,
                      Interval& iv, HitRecord& best, std::uint32_t& best_sphere) const;
    void record_closest(const SurfaceList& surfaces, const Ray& ray, const HitRecord& best, std::uint32_t best_sphere,
                        HitRecord& rec) const;

    WideBvh<kWidth> wide_;
    std::vector<std::uint32_t> items_;  // surface numbers, leaf after leaf (a leaf holds a run of them)
    // Slot by slot, a copy of the item if it is a sphere that does not move (what scenes of
    // spheres are made of), tested straight from here: a sphere's 56 bytes side by side in
    // leaf order, instead of a variant dispatch through surfaces a few hundred bytes apart.
    std::vector<std::optional<Sphere>> spheres_;
    int depth_ = 0;
};

}  // namespace rt
