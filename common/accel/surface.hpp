#pragma once
// A surface (course §9.4.1) binds a shape to what it is made of. The shape is geometry
// only; the surface adds the material. Instancing (chapter 09) wraps a shape in a transform
// without touching it; motion blur (chapter 18) is a sphere's own `motion`.
#include "geometry/shape.hpp"

namespace rt {

struct Surface {
    Shape shape;
    MaterialId material = 0;  // index into the scene's materials; 0 = the default
    SurfaceId id = kNone;     // its place in the scene's surface list, stamped on its hits

    // The closest hit in the interval, as a whole record. False and rec untouched if none.
    bool hit(const Ray& ray, Interval interval, HitRecord& rec) const {
        return hit_record(shape, ray, interval, SurfaceRef{id, material}, rec);
    }
    // The closest hits of a packet of rays from one point (core/wide_packet.hpp): recs[k] and
    // bit k of the answer for ray k, each what hit() gives it.
    unsigned hit_packet(WidePacket& packet, std::span<const Ray> rays, Interval interval, HitRecord* recs) const {
        return hit_records(shape, packet, rays, interval, SurfaceRef{id, material}, recs);
    }
    // Is there any hit in the interval? Stops at the first one found.
    bool occluded(const Ray& ray, Interval interval) const { return rt::occluded(shape, ray, interval); }
    Box bounding_box() const { return rt::bounding_box(shape); }
};

}  // namespace rt
