#pragma once
// Indexed triangle meshes. Triangles share vertices by index, so an edge common to two
// triangles has bit-identical end points in both: what the watertight test needs.
#include "common/triangle.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace rt {

struct MeshData {
    std::vector<Vec3> positions;
    std::vector<std::array<std::uint32_t, 3>> triangles;  // counter-clockwise seen from outside
};

// Throws std::invalid_argument naming the first problem: an index out of range, a
// non-finite position, no triangles.
void validate(const MeshData& mesh, const std::string& what);

// A mesh as a surface. Until the acceleration chapters, hit tests every triangle: the
// brute-force search of §9.4. Degenerate (zero-area) triangles are dropped when the mesh is
// built, so they cost nothing per ray.
class TriangleMesh : public Surface {
public:
    TriangleMesh(std::string name, MeshData data, TriangleTest test = TriangleTest::watertight);
    bool hit(const Ray& ray, Real t0, Real t1, HitRecord& rec) const override;
    Box bounding_box() const override { return box_; }

    const MeshData& data() const { return data_; }
    std::size_t dropped_degenerate() const { return dropped_; }

private:
    MeshData data_;
    TriangleTest test_;
    Box box_;
    std::size_t dropped_ = 0;
};

}  // namespace rt
