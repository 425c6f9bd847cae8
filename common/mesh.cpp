#include "common/mesh.hpp"

#include <cmath>
#include <stdexcept>

namespace rt {

void validate(const MeshData& mesh, const std::string& what) {
    if (mesh.triangles.empty()) throw std::invalid_argument(what + ": mesh has no triangles");
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const Vec3& p = mesh.positions[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::invalid_argument(what + ": vertex " + std::to_string(i) + " is not finite");
    }
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
        for (std::uint32_t v : mesh.triangles[i])
            if (v >= mesh.positions.size())
                throw std::invalid_argument(what + ": triangle " + std::to_string(i) + " uses vertex " +
                                            std::to_string(v) + " of " + std::to_string(mesh.positions.size()));
}

TriangleMesh::TriangleMesh(std::string name, MeshData data, TriangleTest test)
    : Surface(std::move(name)), data_(std::move(data)), test_(test) {
    validate(data_, "mesh '" + this->name() + "'");
    std::vector<std::array<std::uint32_t, 3>> kept;
    kept.reserve(data_.triangles.size());
    for (const auto& t : data_.triangles) {
        const Vec3 n = glm::cross(data_.positions[t[1]] - data_.positions[t[0]],
                                  data_.positions[t[2]] - data_.positions[t[0]]);
        if (glm::dot(n, n) > 0) kept.push_back(t);
    }
    dropped_ = data_.triangles.size() - kept.size();
    data_.triangles = std::move(kept);
    if (data_.triangles.empty()) throw std::invalid_argument("mesh '" + this->name() + "': every triangle is degenerate");
    for (const auto& t : data_.triangles)
        for (std::uint32_t v : t) box_.expand(data_.positions[v]);
}

bool TriangleMesh::hit(const Ray& ray, Real t0, Real t1, HitRecord& rec) const {
    const std::array<std::uint32_t, 3>* best = nullptr;
    TriangleHit best_hit{};
    for (const auto& tri : data_.triangles) {
        const Vec3 &a = data_.positions[tri[0]], &b = data_.positions[tri[1]], &c = data_.positions[tri[2]];
        TriangleHit h;
        if (intersect_triangle(test_, ray, a, b, c, t0, t1, h)) {
            best = &tri;
            best_hit = h;
            t1 = h.t;  // only closer hits from here on
        }
    }
    if (!best) return false;
    const auto& tri = *best;
    fill_triangle_record(data_.positions[tri[0]], data_.positions[tri[1]], data_.positions[tri[2]], best_hit,
                         this, rec);
    rec.primitive = long(best - data_.triangles.data());
    return true;
}

}  // namespace rt
