#pragma once
// The renderer's default search (book §10.5): two levels of the flat BVH of core/flat_bvh.hpp.
// The upper one is built over the scene's surfaces; a mesh surface is one item there and
// searches its triangles through its own BVH (geometry/mesh.hpp), which the mesh's copies
// and instances share. Returns exactly the hits of the brute-force search.
#include "accel/surface_list.hpp"
#include "core/flat_bvh.hpp"

namespace rt {

class TwoLevelBvh {
public:
    explicit TwoLevelBvh(const SurfaceList& surfaces);

    bool hit(const SurfaceList& surfaces, const Ray& ray, Interval interval, HitRecord& rec) const;
    bool occluded(const SurfaceList& surfaces, const Ray& ray, Interval interval) const;

    const FlatBvh& upper() const { return bvh_; }
    // The upper level plus every distinct mesh's BVH, counted once however often it is used.
    std::size_t memory_bytes(const SurfaceList& surfaces) const;
    std::size_t node_count(const SurfaceList& surfaces) const;

private:
    FlatBvh bvh_;
};

}  // namespace rt
