#include "accel/primitive.hpp"

namespace rt {

std::vector<Primitive> primitives_of(const SurfaceList& surfaces) {
    std::vector<Primitive> out;
    for (const Surface& s : surfaces.surfaces()) {
        if (const auto* mesh = std::get_if<Mesh>(&s.shape)) {
            const auto n = std::uint32_t(mesh->data().triangles.size());
            for (std::uint32_t k = 0; k < n; ++k) out.push_back({s.id, k});
        } else {
            out.push_back({s.id, kNone});
        }
    }
    return out;
}

namespace {

// The corners of triangle k of a mesh.
struct Corners {
    const Vec3 &a, &b, &c;
};
Corners corners(const Mesh& mesh, std::uint32_t k) {
    const MeshData& d = mesh.data();
    const auto& t = d.triangles[k];
    return {d.positions[t[0]], d.positions[t[1]], d.positions[t[2]]};
}

}  // namespace

Box bounding_box(const SurfaceList& surfaces, Primitive p) {
    const Surface& s = surfaces[p.surface];
    if (p.triangle == kNone) return s.bounding_box();
    const Corners c = corners(std::get<Mesh>(s.shape), p.triangle);
    Box box;
    box.expand(c.a);
    box.expand(c.b);
    box.expand(c.c);
    return box;
}

bool hit_closer(const Surface& surface, const Ray& ray, Interval interval, HitRecord& best) {
    HitRecord rec;
    if (!surface.hit(ray, Interval{interval.min, widen_far(interval.max)}, rec)) return false;
    if (!closer(rec, best)) return false;
    best = rec;
    return true;
}

bool hit_closer(const SurfaceList& surfaces, Primitive p, const Ray& ray, Interval interval, HitRecord& best) {
    const Surface& s = surfaces[p.surface];
    if (p.triangle == kNone) return hit_closer(s, ray, interval, best);
    const Mesh& mesh = std::get<Mesh>(s.shape);
    const Corners c = corners(mesh, p.triangle);
    TriangleHit h;
    if (!ray_triangle_watertight(ray, c.a, c.b, c.c, Interval{interval.min, widen_far(interval.max)}, h)) return false;
    if (!closer(h.t, s.id, p.triangle, best)) return false;
    best = record(mesh, ray, MeshHit{h, p.triangle, std::nullopt}, SurfaceRef{s.id, s.material});
    return true;
}

bool occluded(const SurfaceList& surfaces, Primitive p, const Ray& ray, Interval interval) {
    const Surface& s = surfaces[p.surface];
    if (p.triangle == kNone) return s.occluded(ray, interval);
    const Corners c = corners(std::get<Mesh>(s.shape), p.triangle);
    TriangleHit h;
    return ray_triangle_watertight(ray, c.a, c.b, c.c, interval, h);
}

}  // namespace rt
