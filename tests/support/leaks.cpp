#include "support/leaks.hpp"

#include <pcg_random.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace rt {

LeakReport measure_leaks(const MeshData& mesh, TriangleTest test, long rays, std::uint64_t seed) {
    // Triangles around each vertex, and the interior edges (exactly two triangles).
    std::vector<std::vector<std::uint32_t>> fan(mesh.positions.size());
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_count;
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
            fan[a].push_back(t);
            ++edge_count[std::minmax(a, b)];
        }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (const auto& [e, n] : edge_count)
        if (n == 2) edges.push_back(e);
    std::vector<std::uint32_t> vertices;
    for (std::uint32_t v = 0; v < fan.size(); ++v)
        if (!fan[v].empty()) vertices.push_back(v);

    Box box;
    for (const Vec3& p : mesh.positions) box.expand(p);
    const Vec3 center = (box.min + box.max) / Real(2);
    const Real radius = Real(3) * glm::length(box.max - box.min);

    pcg32 rng(seed);
    auto uniform = [&] { return double(rng()) * 0x1p-32; };
    LeakReport report;
    std::vector<std::uint32_t> candidates;
    for (long i = 0; i < rays; ++i) {
        Vec3 target;
        candidates.clear();
        if (i % 4 != 3 && !edges.empty()) {
            const auto& [a, b] = edges[std::size_t(uniform() * double(edges.size()))];
            const Real s = Real(0.05 + 0.9 * uniform());
            target = mesh.positions[a] + s * (mesh.positions[b] - mesh.positions[a]);
            candidates = fan[a];
            candidates.insert(candidates.end(), fan[b].begin(), fan[b].end());
            ++report.edge_rays;
        } else {
            const std::uint32_t v = vertices[std::size_t(uniform() * double(vertices.size()))];
            target = mesh.positions[v];
            candidates = fan[v];
            ++report.vertex_rays;
        }
        // A uniformly random origin on the sphere around the mesh, from which the target is
        // not on the silhouette: the ray must cross from one side of the surface to the other
        // there (all triangles around the target face it the same way), or a miss would be
        // a graze, not a leak.
        Ray ray;
        for (bool crosses = false; !crosses;) {
            const double z = 2 * uniform() - 1, phi = 2 * M_PI * uniform(), r = std::sqrt(1 - z * z);
            const Vec3 origin = center + radius * Vec3(Real(r * std::cos(phi)), Real(r * std::sin(phi)), Real(z));
            ray = Ray{origin, target - origin};
            int front = 0, back = 0;
            for (std::uint32_t t : candidates) {
                const auto& tri = mesh.triangles[t];
                const Vec3 n = glm::cross(mesh.positions[tri[1]] - mesh.positions[tri[0]],
                                          mesh.positions[tri[2]] - mesh.positions[tri[0]]);
                const Real side = glm::dot(n, ray.direction);
                front += side < 0;
                back += side > 0;
            }
            crosses = front == int(candidates.size()) || back == int(candidates.size());
        }
        bool hit = false;
        for (std::uint32_t t : candidates) {
            const auto& tri = mesh.triangles[t];
            TriangleHit h;
            const Vec3 &A = mesh.positions[tri[0]], &B = mesh.positions[tri[1]], &C = mesh.positions[tri[2]];
            hit = intersect_triangle(test, ray, A, B, C, Interval{}, h);
            if (hit) break;
        }
        ++report.rays;
        report.leaks += !hit;
    }
    return report;
}

}  // namespace rt
