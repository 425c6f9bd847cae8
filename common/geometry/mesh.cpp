#include "geometry/mesh.hpp"

#include "geometry/limits.hpp"

#include <cmath>
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
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
        for (std::uint32_t v : mesh.triangles[i])
            if (v >= mesh.positions.size())
                throw std::invalid_argument(what + ": triangle " + std::to_string(i) + " uses vertex " +
                                            std::to_string(v) + " of " + std::to_string(mesh.positions.size()));
}

Mesh::Mesh(MeshData data) {
    validate(data, "mesh");
    std::vector<std::array<std::uint32_t, 3>> kept;
    kept.reserve(data.triangles.size());
    for (const auto& t : data.triangles) {
        const Vec3 n =
            glm::cross(data.positions[t[1]] - data.positions[t[0]], data.positions[t[2]] - data.positions[t[0]]);
        if (glm::dot(n, n) > 0) kept.push_back(t);
    }
    dropped_ = data.triangles.size() - kept.size();
    data.triangles = std::move(kept);
    if (data.triangles.empty()) throw std::invalid_argument("mesh: every triangle is degenerate");
    for (const auto& t : data.triangles)
        for (std::uint32_t v : t) box_.expand(data.positions[v]);
    data_ = std::make_shared<const MeshData>(std::move(data));
}

bool hit(const Mesh& mesh, const Ray& ray, Interval interval, MeshHit& result) {
    const MeshData& d = mesh.data();
    bool found = false;
    for (std::size_t k = 0; k < d.triangles.size(); ++k) {
        const auto& tri = d.triangles[k];
        TriangleHit h;
        if (ray_triangle_watertight(ray, d.positions[tri[0]], d.positions[tri[1]], d.positions[tri[2]], interval, h)) {
            result = MeshHit{h, std::uint32_t(k)};
            interval.max = h.t;  // only closer hits from here on
            found = true;
        }
    }
    return found;
}

bool occluded(const Mesh& mesh, const Ray& ray, Interval interval) {
    const MeshData& d = mesh.data();
    TriangleHit h;
    for (const auto& tri : d.triangles)
        if (ray_triangle_watertight(ray, d.positions[tri[0]], d.positions[tri[1]], d.positions[tri[2]], interval, h))
            return true;
    return false;
}

HitRecord record(const Mesh& mesh, const Ray&, const MeshHit& h, SurfaceRef who) {
    const MeshData& d = mesh.data();
    const auto& tri = d.triangles[h.index];
    return triangle_record(d.positions[tri[0]], d.positions[tri[1]], d.positions[tri[2]], h.triangle, who, h.index);
}

}  // namespace rt
