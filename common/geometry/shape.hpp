#pragma once
// A shape is geometry only: one of a closed set of plain structs. Queries on a Shape are a
// switch over that set (dispatch, core/dispatch.hpp), not a virtual call through a pointer,
// so the compiler can inline each kind's test into the loop that calls it.
#include "core/dispatch.hpp"
#include "geometry/csg.hpp"
#include "geometry/cuboid.hpp"
#include "geometry/instance.hpp"
#include "geometry/mesh.hpp"
#include "geometry/polygon.hpp"
#include "geometry/sphere.hpp"
#include "geometry/triangle.hpp"

#include <bit>
#include <concepts>
#include <iterator>
#include <span>
#include <variant>

namespace rt {

// A struct rather than an alias so that Instance can name it before it is complete.
struct Shape : std::variant<Sphere, Triangle, Polygon, Mesh, Instance, Cuboid, Csg> {
    using variant::variant;
};

// The kind's name, as scene files and --pick say it.
inline const char* shape_kind(const Shape& shape) {
    constexpr const char* names[] = {"sphere", "triangle", "polygon", "mesh", "instance", "box", "csg"};
    static_assert(std::size(names) == std::variant_size_v<Shape::variant>, "a name for every kind of shape");
    return names[shape.index()];
}

// What a shape's own data takes in memory; a mesh counts its arrays, which its copies and
// instances share. For --stats.
std::size_t memory_bytes(const Shape& shape);

// The closest hit of one shape in the interval, as a whole record owned by `who`. The
// shape's own test finds the small result; `record` builds everything else from it.
template <class S>
bool hit_record(const S& shape, const Ray& ray, Interval interval, SurfaceRef who, HitRecord& rec) {
    typename S::Hit h;  // SphereHit, TriangleHit, PolygonHit, MeshHit, ...
    if (!hit(shape, ray, interval, h)) return false;
    rec = record(shape, ray, h, who);
    return true;
}

// A moving sphere (chapter 18) is tested where it stands at the ray's time.
inline bool hit_record(const Sphere& sphere, const Ray& ray, Interval interval, SurfaceRef who, HitRecord& rec) {
    const Sphere s = sphere.moves() ? sphere.at(ray.time) : sphere;
    SphereHit h;
    if (!hit(s, ray, interval, h)) return false;
    rec = record(s, ray, h, who);
    return true;
}

template <std::same_as<Shape> S>
bool hit_record(const S& shape, const Ray& ray, Interval interval, SurfaceRef who, HitRecord& rec) {
    return dispatch(shape, [&](const auto& s) { return hit_record(s, ray, interval, who, rec); });
}

// The closest hits of a packet of rays from one point (core/wide_packet.hpp), each as
// hit_record finds it: recs[k], and bit k of the answer, for ray k. A mesh searches its tree
// once for them all (geometry/mesh.hpp); any other shape tests one ray after another.
template <class S>
unsigned hit_records(const S& shape, WidePacket&, std::span<const Ray> rays, Interval interval, SurfaceRef who,
                     HitRecord* recs) {
    return one_by_one(rays.size(), [&](std::size_t k) { return hit_record(shape, rays[k], interval, who, recs[k]); });
}

inline unsigned hit_records(const Mesh& mesh, WidePacket& packet, std::span<const Ray> rays, Interval interval,
                            SurfaceRef who, HitRecord* recs) {
    MeshHit hits[kPacketRays];
    const unsigned found = hit_packet(mesh, packet, rays, interval, hits);
    for (unsigned m = found; m != 0; m &= m - 1) {
        const int k = std::countr_zero(m);
        recs[k] = record(mesh, rays[std::size_t(k)], hits[k], who);
    }
    return found;
}

template <std::same_as<Shape> S>
unsigned hit_records(const S& shape, WidePacket& packet, std::span<const Ray> rays, Interval interval, SurfaceRef who,
                     HitRecord* recs) {
    return dispatch(shape, [&](const auto& s) { return hit_records(s, packet, rays, interval, who, recs); });
}

// Any hit in the interval: what a shadow ray asks. For most shapes that is their own test;
// a mesh has an overload of its own (geometry/mesh.hpp) that stops at its first triangle.
template <class S>
bool occluded(const S& shape, const Ray& ray, Interval interval) {
    typename S::Hit h;
    return hit(shape, ray, interval, h);
}

inline bool occluded(const Sphere& sphere, const Ray& ray, Interval interval) {
    SphereHit h;
    return hit(sphere.moves() ? sphere.at(ray.time) : sphere, ray, interval, h);
}

template <std::same_as<Shape> S>
bool occluded(const S& shape, const Ray& ray, Interval interval) {
    return dispatch(shape, [&](const auto& s) { return occluded(s, ray, interval); });
}

// Whether anything in the shape moves (chapter 18): only then do rays need a time.
bool moves(const Shape& shape);

// The whole variant only: a kind without a bounding_box of its own must not compile by
// converting to a Shape and asking this one again.
template <std::same_as<Shape> S>
Box bounding_box(const S& shape) {
    return dispatch(shape, [](const auto& s) { return bounding_box(s); });
}

}  // namespace rt
