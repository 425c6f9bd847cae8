#include "geometry/mesh.hpp"

#include "core/opaque.hpp"
#include "geometry/limits.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace rt {

void validate(const MeshData& mesh, const std::string& what) {
    if (mesh.triangles.empty()) throw std::invalid_argument(what + ": mesh has no triangles");
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const Vec3& p = mesh.positions[i];
        for (int k = 0; k < 3; ++k)
            if (!limits::contains(limits::coordinate, double(p[k])))
                throw std::invalid_argument(what + ": vertex " + std::to_string(i + 1) + ": " +
                                            limits::refuse(limits::coordinate, double(p[k])));
    }
    if (!mesh.normal_triangles.empty() && mesh.normal_triangles.size() != mesh.triangles.size())
        throw std::invalid_argument(what + ": vertex normals given for some triangles only");
    for (std::size_t i = 0; i < mesh.normals.size(); ++i)
        if (!std::isfinite(mesh.normals[i].x) || !std::isfinite(mesh.normals[i].y) || !std::isfinite(mesh.normals[i].z))
            throw std::invalid_argument(what + ": vertex normal " + std::to_string(i + 1) + " is not finite");
    for (std::size_t i = 0; i < mesh.normal_triangles.size(); ++i)
        for (std::uint32_t v : mesh.normal_triangles[i])
            if (v >= mesh.normals.size())
                throw std::invalid_argument(what + ": triangle " + std::to_string(i) + " uses normal " +
                                            std::to_string(v) + " of " + std::to_string(mesh.normals.size()));
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
        for (std::uint32_t v : mesh.triangles[i])
            if (v >= mesh.positions.size())
                throw std::invalid_argument(what + ": triangle " + std::to_string(i) + " uses vertex " +
                                            std::to_string(v) + " of " + std::to_string(mesh.positions.size()));
}

namespace {

std::shared_ptr<const MeshAccel> build_accel(const MeshData& d) {
    std::vector<Box> boxes(d.triangles.size());
    for (std::size_t k = 0; k < boxes.size(); ++k)
        for (std::uint32_t v : d.triangles[k]) boxes[k].expand(d.positions[v]);
    const FlatBvh bvh = build_bvh(boxes, 4, 4);  // a leaf is one block
    auto a = std::make_shared<MeshAccel>();
    a->wide = collapse<kMeshBvhWidth>(bvh);
    const std::size_t leaves = (bvh.nodes.size() + 1) / 2;  // every inner node has two children
    a->blocks.reserve(leaves);
    // Each leaf's triangles into a block, and the leaf renumbered to it.
    const auto block = [&](std::uint32_t first, std::uint32_t count) {
        a->blocks.push_back(pack(std::span(bvh.items).subspan(first, count), d.positions.data(), d.triangles.data()));
        return std::uint32_t(a->blocks.size() - 1);
    };
    if (a->wide.root_is_leaf) block(0, a->wide.root_count);
    for (auto& node : a->wide.nodes)
        for (int c = 0; c < kMeshBvhWidth; ++c)
            if (is_leaf(node.child[c]))
                node.child[c] =
                    leaf_ref(block(leaf_first(node.child[c]), leaf_count(node.child[c])), leaf_count(node.child[c]));
    // The Real corners, unless float holds every one of them.
    if (std::any_of(a->blocks.begin(), a->blocks.end(), [](const TriangleBlock& b) { return !b.exact; })) {
        a->corners.reserve(4 * a->blocks.size());
        for (const TriangleBlock& b : a->blocks)
            for (std::uint32_t t : b.index) {
                const auto& c = d.triangles[t];
                a->corners.push_back({d.positions[c[0]], d.positions[c[1]], d.positions[c[2]]});
            }
    }
    return a;
}

}  // namespace

Mesh::Mesh(MeshData data) {
    validate(data, "mesh");
    std::vector<std::array<std::uint32_t, 3>> kept, kept_normals;
    kept.reserve(data.triangles.size());
    for (std::size_t k = 0; k < data.triangles.size(); ++k) {
        const auto& t = data.triangles[k];
        const Vec3 n =
            glm::cross(data.positions[t[1]] - data.positions[t[0]], data.positions[t[2]] - data.positions[t[0]]);
        if (!(glm::dot(n, n) > 0)) continue;
        kept.push_back(t);
        if (!data.normal_triangles.empty()) kept_normals.push_back(data.normal_triangles[k]);
    }
    dropped_ = data.triangles.size() - kept.size();
    data.triangles = std::move(kept);
    data.normal_triangles = std::move(kept_normals);
    if (data.triangles.empty()) throw std::invalid_argument("mesh: every triangle is degenerate");
    for (const auto& t : data.triangles)
        for (std::uint32_t v : t) box_.expand(data.positions[v]);
    data_ = std::make_shared<const MeshData>(std::move(data));
    accel_ = build_accel(*data_);
}

// A closest-hit query's view of the ray: 1/d once, for the mesh's box, the tree's boxes and
// the triangles' shear. The shear is made at the first leaf the ray reaches: many rays that
// come into a mesh's box reach none.
struct MeshRay {
    const Ray& ray;
    Vec3 inv;
    std::optional<WideRay<kMeshBvhWidth>> wide;
    std::optional<RayShear> shear_;

    // `wide` stays empty when the ray misses the mesh's box: then nothing else is made. A
    // camera ray at a mesh alone in its scene meets no other box first, and most such rays
    // that miss the mesh miss its box too.
    MeshRay(const Ray& r, const Mesh& mesh, Interval interval) : ray(r), inv(Real(1) / r.direction) {
        if (might_hit(mesh.box(), ray, inv, interval)) wide.emplace(ray, inv);
    }

    const RayShear& shear() {
        if (!shear_) shear_.emplace(ray, inv);
        return *shear_;
    }
};

// The closest hit so far: its t and triangle number (kNone before the first).
struct Closest {
    Real t;
    std::uint32_t index = kNone;
};

// The lanes of block b that the float filter kept, decided by the exact test against the
// interval as it stands when the block is reached; a hit is kept only if it is closer in the
// one order (lower index at equal t). Out of line, with its arguments in registers: about
// half the leaves a hit ray reaches keep no lane, and the search's loop stays small.
// The searches' leaf tests are inlined into them. Spelled through a name: clang-format 14 and
// 19 (Debian 12 and 13) space "Interval& iv) __attribute__((...))" differently, and the house
// style is checked with both.
#define RTLAB_INLINE_LEAF __attribute__((always_inline))

[[gnu::noinline]] bool exact_closest(unsigned lanes, const MeshAccel& a, std::uint32_t b, const Ray& ray, Real t_min,
                                     Interval& iv, Closest& best, MeshHit& result) {
    bool closer = false;
    exact_hits(lanes, a.blocks[b], a.corners_of(b), ray, Interval{t_min, widen_far(iv.max)},
               [&](std::uint32_t index, const TriangleHit& h, const std::array<Vec3, 3>& corners) {
                   if (!(h.t <= best.t) || (h.t == best.t && index > best.index)) return false;
                   best = Closest{h.t, index};
                   result.triangle = h;  // field by field: a whole MeshHit built and copied cost more
                   result.index = index;
                   result.corners = corners;
                   iv.max = h.t;
                   closer = true;
                   return false;
               });
    return closer;
}

bool hit(const Mesh& mesh, const Ray& ray, Interval interval, MeshHit& result) {
    const MeshAccel& a = mesh.accel();
    interval = in_registers(interval);
    MeshRay r(ray, mesh, interval);
    if (!r.wide) return false;
    const Real t_min = interval.min;
    Closest best{interval.max};
    return closest_hit(
        a.wide, *r.wide, interval,
        [&](std::uint32_t b, std::uint32_t, Interval& iv) RTLAB_INLINE_LEAF {
            const unsigned lanes = candidates(a.blocks[b], r.shear(), iv);
            return lanes != 0 && exact_closest(lanes, a, b, ray, t_min, iv, best, result);
        },
        [&](std::uint32_t b) { prefetch(a.blocks[b]); });
}

unsigned hit_packet(const Mesh& mesh, WidePacket& packet, std::span<const Ray> rays, Interval interval,
                    MeshHit* results) {
    const MeshAccel& a = mesh.accel();
    // Each ray's search as hit() keeps it: its interval, its best hit so far, and its shear,
    // made at the first leaf it reaches (bit k of `sheared` says ray k's is made).
    struct Search {
        Interval iv;
        Closest best;
    };
    Search search[kPacketRays];
    RayShear shear[kPacketRays];
    for (std::size_t k = 0; k < rays.size(); ++k) search[k] = {interval, Closest{interval.max}};
    unsigned found = 0, sheared = 0;
    closest_hits(
        a.wide, packet,
        [&](std::uint32_t b, std::uint32_t, unsigned which) {
            bool narrowed = false;
            for (; which != 0; which &= which - 1) {
                const int k = std::countr_zero(which);
                Search& s = search[k];
                const Ray& ray = rays[std::size_t(k)];
                if (!(sheared >> k & 1)) {
                    shear[k] = RayShear(ray);
                    sheared |= 1u << k;
                }
                const unsigned lanes = candidates(a.blocks[b], shear[k], s.iv);
                if (lanes != 0 && exact_closest(lanes, a, b, ray, interval.min, s.iv, s.best, results[k])) {
                    found |= 1u << k;
                    packet.narrow(k, s.iv.max);
                    narrowed = true;
                }
            }
            return narrowed;
        },
        [&](std::uint32_t b) { prefetch(a.blocks[b]); });
    return found;
}

bool occluded(const Mesh& mesh, const Ray& ray, Interval interval) {
    const MeshAccel& a = mesh.accel();
    interval = in_registers(interval);
    // Unlike a camera ray, a shadow ray is not tested against the mesh's box first, and its
    // shear is made before the search, not at the first leaf. It leaves a surface: inside
    // this mesh's box when the surface is the mesh's, and past the upper level's test of the
    // box when it is not, so the test in double would be paid for nothing (bunny shadow rays,
    // callgrind: 1,106 -> 1,062 instructions unblocked, 1,245 -> 1,201 blocked; the root's
    // eight float boxes still turn away a ray that misses). And it reaches at least the leaf
    // of that surface, where making the shear, inside the search, cost the search's vector
    // registers saved and restored around the call.
    const Vec3 inv = Real(1) / ray.direction;
    const WideRay<kMeshBvhWidth> wide(ray, inv);
    const RayShear shear(ray, inv);
    return any_hit(
        a.wide, wide, interval,
        [&](std::uint32_t b, std::uint32_t, Interval& iv) RTLAB_INLINE_LEAF {
            const auto corners = [&] { return a.corners_of(b); };
            return blocks_ray(a.blocks[b], corners, shear, ray, iv);
        },
        [&](std::uint32_t b) { prefetch(a.blocks[b]); });
}

HitRecord record(const Mesh& mesh, const Ray&, const MeshHit& h, SurfaceRef who) {
    const MeshData& d = mesh.data();
    HitRecord rec;
    if (h.corners) {
        const auto& c = *h.corners;
        rec = triangle_record(c[0], c[1], c[2], h.triangle, who, h.index);
    } else {
        const auto& tri = d.triangles[h.index];
        rec = triangle_record(d.positions[tri[0]], d.positions[tri[1]], d.positions[tri[2]], h.triangle, who, h.index);
    }
    if (mesh.smooth()) {
        const auto& nt = d.normal_triangles[h.index];
        const Real alpha = 1 - h.triangle.beta - h.triangle.gamma;
        const Vec3 n = unit_vector(alpha * d.normals[nt[0]] + h.triangle.beta * d.normals[nt[1]] +
                                   h.triangle.gamma * d.normals[nt[2]]);
        // Vertex normals that cancel out (or point nowhere) leave the flat normal; ones that
        // point into the surface are turned to the side the geometric normal is on.
        if (glm::dot(n, n) > 0) rec.shading_normal = glm::dot(n, rec.normal) < 0 ? -n : n;
    }
    return rec;
}

Mesh Mesh::smoothed() const {
    MeshData data = *data_;
    compute_vertex_normals(data);
    // Only the normals change: the triangles, their box and their tree are this mesh's, so
    // they are shared, not validated and built again.
    Mesh result = *this;
    result.data_ = std::make_shared<const MeshData>(std::move(data));
    return result;
}

void compute_vertex_normals(MeshData& mesh) {
    mesh.normals.assign(mesh.positions.size(), Vec3(0));
    for (const auto& t : mesh.triangles) {
        // The cross product's length is twice the triangle's area: larger triangles weigh more.
        const Vec3 n =
            glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]);
        for (std::uint32_t v : t) mesh.normals[v] += n;
    }
    for (Vec3& n : mesh.normals) n = unit_vector(n);
    mesh.normal_triangles = mesh.triangles;
}

std::size_t memory_bytes(const MeshData& mesh) {
    return mesh.positions.size() * sizeof(Vec3) + mesh.triangles.size() * sizeof(mesh.triangles[0]) +
           mesh.normals.size() * sizeof(Vec3) + mesh.normal_triangles.size() * sizeof(mesh.normal_triangles[0]);
}

}  // namespace rt
