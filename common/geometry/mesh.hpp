#pragma once
// Indexed triangle meshes. Triangles share vertices by index, so an edge common to two
// triangles has bit-identical end points in both: what the watertight test needs.
#include "core/wide_bvh.hpp"
#include "core/wide_packet.hpp"
#include "geometry/triangle.hpp"
#include "geometry/triangle_block.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rt {

struct MeshData {
    std::vector<Vec3> positions;
    std::vector<std::array<std::uint32_t, 3>> triangles;  // counter-clockwise seen from outside
    // Optional vertex normals for smooth shading: normal_triangles[k] indexes `normals` for
    // the corners of triangles[k]. Both empty for a mesh shaded flat.
    std::vector<Vec3> normals;
    std::vector<std::array<std::uint32_t, 3>> normal_triangles;
};

// Gives every vertex the area-weighted average of the normals of the triangles around it,
// so that the mesh shades smoothly (a sphere made of triangles looks round).
void compute_vertex_normals(MeshData& mesh);

// What the mesh's arrays take in memory, for --stats.
std::size_t memory_bytes(const MeshData& mesh);

// Throws std::invalid_argument naming the first problem: an index out of range, a
// position outside limits::coordinate (or not finite), no triangles.
void validate(const MeshData& mesh, const std::string& what);

// Which triangle a ray met, and where.
struct MeshHit {
    TriangleHit triangle;
    std::uint32_t index;
    // Its corners, when the search had them at hand (a block's floats or MeshAccel::corners):
    // the record then takes them from here instead of through the index arrays, two trips
    // to memory on a big mesh.
    std::optional<std::array<Vec3, 3>> corners;
};

// How many children a node of a mesh's BVH has: eight floats are one AVX register, so a
// node's boxes take one instruction per plane (book §10.5).
inline constexpr int kMeshBvhWidth = 8;

// A mesh's own search structure (book §10.5): a wide BVH over its triangles, whose leaves
// are blocks of up to four triangles with their corners copied out side by side, so a leaf
// is one read of consecutive memory and one pass of vector instructions.
struct MeshAccel {
    WideBvh<kMeshBvhWidth> wide;  // a leaf child's first item is its block's number
    std::vector<TriangleBlock, SearchAllocator<TriangleBlock>> blocks;
    // corners[4 b + lane]: the exact test's, in Real; empty when every block holds its own
    // exactly (TriangleBlock::exact).
    std::vector<std::array<Vec3, 3>, SearchAllocator<std::array<Vec3, 3>>> corners;

    const std::array<Vec3, 3>* corners_of(std::uint32_t block) const {
        return corners.empty() ? nullptr : corners.data() + 4 * std::size_t(block);
    }

    std::size_t memory_bytes() const {
        return wide.memory_bytes() + blocks.size() * sizeof(TriangleBlock) + corners.size() * sizeof(corners[0]);
    }
};

// A mesh: geometry only. Its data is shared, so copies of a Mesh (two surfaces wearing
// different materials, two instances) cost one pointer, not a copy of the triangles, and
// share one BVH over them: the lower level of the two-level fast path. Degenerate
// (zero-area) triangles are dropped once, here, so they cost nothing per ray.
class Mesh {
public:
    using Hit = MeshHit;

    explicit Mesh(MeshData data);

    const MeshData& data() const { return *data_; }
    const MeshAccel& accel() const { return *accel_; }
    bool smooth() const { return !data_->normal_triangles.empty(); }
    // The same mesh with vertex normals computed (compute_vertex_normals): shaded smoothly.
    Mesh smoothed() const;
    std::size_t dropped_degenerate() const { return dropped_; }
    const Box& box() const { return box_; }

private:
    std::shared_ptr<const MeshData> data_;
    std::shared_ptr<const MeshAccel> accel_;
    std::size_t dropped_ = 0;
    Box box_;
};

// The closest hit through the mesh's BVH; at equal t the lower triangle index, so the
// answer is the brute-force one (geometry/hit_record.hpp, closer).
bool hit(const Mesh& mesh, const Ray& ray, Interval interval, MeshHit& result);
// The closest hits of a packet of rays from one point (core/wide_packet.hpp) over `interval`,
// each the hit that hit() finds for it: results[k] and bit k of the answer for ray k.
unsigned hit_packet(const Mesh& mesh, WidePacket& packet, std::span<const Ray> rays, Interval interval,
                    MeshHit* results);
// True as soon as any triangle is hit in the interval: shadow rays need no closest hit.
bool occluded(const Mesh& mesh, const Ray& ray, Interval interval);
HitRecord record(const Mesh& mesh, const Ray& ray, const MeshHit& h, SurfaceRef who = {});
inline Box bounding_box(const Mesh& mesh) {
    return mesh.box();
}

}  // namespace rt
