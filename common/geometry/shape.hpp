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

#include <variant>

namespace rt {

// A struct rather than an alias so that Instance can name it before it is complete.
struct Shape : std::variant<Sphere, Triangle, Polygon, Mesh, Instance, Cuboid, Csg> {
    using variant::variant;
};

// The kind's name, as scene files and --pick say it.
inline const char* shape_kind(const Shape& shape) {
    constexpr const char* names[] = {"sphere", "triangle", "polygon", "mesh", "instance", "box", "csg"};
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

inline bool hit_record(const Shape& shape, const Ray& ray, Interval interval, SurfaceRef who, HitRecord& rec) {
    return dispatch(shape, [&](const auto& s) { return hit_record(s, ray, interval, who, rec); });
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

inline bool occluded(const Shape& shape, const Ray& ray, Interval interval) {
    return dispatch(shape, [&](const auto& s) { return occluded(s, ray, interval); });
}

// Whether anything in the shape moves (chapter 18): only then do rays need a time.
bool moves(const Shape& shape);

inline Box bounding_box(const Shape& shape) {
    return std::visit([](const auto& s) { return bounding_box(s); }, shape);
}

}  // namespace rt
