#pragma once
#include "core/real.hpp"

#include <cstdint>

namespace rt {

// Surfaces and materials are addressed by index into the scene's lists: small, plain
// records that an acceleration structure can hold by the million.
using SurfaceId = std::uint32_t;
using MaterialId = std::uint32_t;
inline constexpr std::uint32_t kNone = ~std::uint32_t(0);

// Who owns a hit: the surface (shape + material) the library stamps on every record.
struct SurfaceRef {
    SurfaceId surface = kNone;
    MaterialId material = 0;  // 0: the scene's default material
};

// @book hit-record
// Everything a successful query reports. Always built whole, by one library function per
// shape kind (`record`), and assigned in one piece: no field can survive from an earlier,
// farther hit on another surface.
struct HitRecord {
    Real t = kInfinity;
    Vec3 p{0};       // the hit point
    Vec3 normal{0};  // unit geometric normal, pointing out of the surface (never flipped)
    // Unit normal for shading: the geometric one, except on meshes with vertex normals, where
    // it is interpolated (smooth shading). Offsets and inside/outside use `normal` only.
    Vec3 shading_normal{0};
    // How far p may lie off the true surface, along the normal: the rounding of p and of the
    // shape's own test for a ray that starts near it, which grow with the shape's size and
    // place, not with p's coordinates. 0 for shapes whose error offset_origin's step already
    // covers. spawn_ray starts secondary rays at least this far out (book §6.3).
    Real error = 0;
    SurfaceId surface = kNone;
    MaterialId material = 0;
    std::uint32_t primitive = kNone;  // which triangle of a mesh, for picking
    std::uint32_t part = kNone;       // which operand of a CSG object (Csg::describe), for picking
    // Barycentric coordinates, for the shapes that have them (triangles).
    bool has_barycentrics = false;
    Real beta = 0;
    Real gamma = 0;
};
// @book-end

// The one order in which every search ranks hits, so that brute force and every
// acceleration structure return the same hit: the nearer first; at the same distance the
// lower surface id, then the lower primitive (a ray through an edge meets two triangles at
// the same t). Is a hit at t on (surface, primitive) closer than `best`?
inline bool closer(Real t, SurfaceId surface, std::uint32_t primitive, const HitRecord& best) {
    if (t != best.t) return t < best.t;
    if (surface != best.surface) return surface < best.surface;
    return primitive < best.primitive;
}
inline bool closer(const HitRecord& a, const HitRecord& best) {
    return closer(a.t, a.surface, a.primitive, best);
}

}  // namespace rt
