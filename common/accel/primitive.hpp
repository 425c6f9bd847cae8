#pragma once
// What the scene-level structures of chapters 10-12 sort: primitives. A mesh surface is
// broken into its triangles, so that a structure over the scene also searches inside the
// meshes; every other surface (a sphere, a polygon, an instance) is one primitive. An
// instance stays whole: its inside is searched through its base shape, whose mesh brings its
// own BVH (geometry/mesh.hpp).
#include "accel/surface_list.hpp"

#include <vector>

namespace rt {

struct Primitive {
    SurfaceId surface;
    std::uint32_t triangle = kNone;  // the triangle of a mesh surface; kNone: the whole surface
};

// Every surface's primitives, in surface order (a mesh's triangles in index order).
std::vector<Primitive> primitives_of(const SurfaceList& surfaces);
Box bounding_box(const SurfaceList& surfaces, Primitive p);

// Tests one primitive and keeps its hit in `best` if it is closer than what `best` holds,
// in the one order of `closer` (geometry/hit_record.hpp). `best` starts with t at the far
// end of the interval and no surface; the interval's far end is the best t so far. True if
// `best` changed. The test looks a few ulps past the far end (widen_far), so the answer does
// not depend on the order in which primitives are tried.
bool hit_closer(const SurfaceList& surfaces, Primitive p, const Ray& ray, Interval interval, HitRecord& best);
// The same for a whole surface (the fast path's upper level: a mesh searches itself).
bool hit_closer(const Surface& surface, const Ray& ray, Interval interval, HitRecord& best);

// Is there any hit of this primitive in the interval?
bool occluded(const SurfaceList& surfaces, Primitive p, const Ray& ray, Interval interval);

// The start of a search: nothing found yet, and only hits up to the interval's far end count.
inline HitRecord no_hit_before(Real t_max) {
    HitRecord best;
    best.t = t_max;
    return best;
}

}  // namespace rt
