#include "geometry/procedural.hpp"

#include "geometry/limits.hpp"

#include <pcg_random.hpp>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace rt {

namespace {

void check(const limits::Range& range, long long value) {
    if (!limits::contains(range, double(value))) throw std::invalid_argument(limits::refuse(range, double(value)));
}

}  // namespace

MeshData icosphere(const Vec3& center, Real radius, int subdivisions) {
    check(limits::icosphere_subdivisions, subdivisions);
    if (!(radius > 0)) throw std::invalid_argument("icosphere: radius must be > 0");
    // Unit-sphere directions in double, so that float and double builds share one topology
    // and differ only in the final rounding.
    const double g = (1 + std::sqrt(5.0)) / 2;
    std::vector<glm::dvec3> dirs = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                                    {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    for (auto& d : dirs) d = glm::normalize(d);
    std::vector<std::array<std::uint32_t, 3>> tris = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                                      {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                                      {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                                      {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoint;
        auto mid = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            auto it = midpoint.find(key);
            if (it != midpoint.end()) return it->second;
            dirs.push_back(glm::normalize(dirs[a] + dirs[b]));
            const auto index = std::uint32_t(dirs.size() - 1);
            midpoint.emplace(key, index);
            return index;
        };
        std::vector<std::array<std::uint32_t, 3>> next;
        for (const auto& t : tris) {
            const std::uint32_t ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
            next.push_back({t[0], ab, ca});
            next.push_back({t[1], bc, ab});
            next.push_back({t[2], ca, bc});
            next.push_back({ab, bc, ca});
        }
        tris = std::move(next);
    }
    MeshData mesh;
    for (const auto& d : dirs) mesh.positions.push_back(center + radius * Vec3(d));
    mesh.triangles = std::move(tris);
    return mesh;
}

MeshData subdivided_cube(const Vec3& center, Real size, int n) {
    check(limits::cube_subdivisions, n);
    if (!(size > 0)) throw std::invalid_argument("subdivided_cube: size must be > 0");
    // Lattice points of the cube's surface, keyed by integer coordinates so that the faces
    // share their border vertices exactly.
    std::map<std::array<int, 3>, std::uint32_t> index;
    MeshData mesh;
    auto vertex = [&](std::array<int, 3> k) {
        auto it = index.find(k);
        if (it != index.end()) return it->second;
        const Vec3 p = center + size * (Vec3(Real(k[0]), Real(k[1]), Real(k[2])) / Real(n) - Real(0.5));
        mesh.positions.push_back(p);
        return index[k] = std::uint32_t(mesh.positions.size() - 1);
    };
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const int u_axis = (axis + 1) % 3, v_axis = (axis + 2) % 3;
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    auto at = [&](int di, int dj) {
                        std::array<int, 3> k{};
                        k[axis] = side * n;
                        k[u_axis] = i + di;
                        k[v_axis] = j + dj;
                        return vertex(k);
                    };
                    const std::uint32_t a = at(0, 0), b = at(1, 0), c = at(1, 1), d = at(0, 1);
                    // u x v points along +axis; flip on the negative side so normals face out.
                    if (side == 1) {
                        mesh.triangles.push_back({a, b, c});
                        mesh.triangles.push_back({a, c, d});
                    } else {
                        mesh.triangles.push_back({a, c, b});
                        mesh.triangles.push_back({a, d, c});
                    }
                }
        }
    return mesh;
}

MeshData terrain(const Vec3& center, Real size, Real height, int n) {
    check(limits::terrain_cells, n);
    if (!(size > 0)) throw std::invalid_argument("terrain: size must be > 0");
    MeshData mesh;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const double x = double(i) / n - 0.5, z = double(j) / n - 0.5;
            const double y = 0.5 * std::sin(7 * x + 1) * std::cos(5 * z) + 0.3 * std::sin(13 * x * z + 2 * z) +
                             0.2 * std::cos(17 * x - 11 * z);
            mesh.positions.push_back(center + Vec3(Real(x * size), Real(y) * height, Real(z * size)));
        }
    const auto at = [n](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            // Counter-clockwise seen from above (+y).
            mesh.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    return mesh;
}

MeshData triangle_soup(const Vec3& center, Real size, Real scale, int count, std::uint64_t seed) {
    check(limits::soup_count, count);
    pcg32 rng(seed);
    auto uniform = [&] { return double(rng()) * 0x1p-32; };
    MeshData mesh;
    for (int k = 0; k < count; ++k) {
        const glm::dvec3 c{uniform() - 0.5, uniform() - 0.5, uniform() - 0.5};  // braces: drawn x, y, z in order
        const auto base = std::uint32_t(mesh.positions.size());
        for (int v = 0; v < 3; ++v) {
            const glm::dvec3 offset{uniform() - 0.5, uniform() - 0.5, uniform() - 0.5};
            mesh.positions.push_back(center + Vec3(c * double(size) + offset * double(scale)));
        }
        mesh.triangles.push_back({base, base + 1, base + 2});
    }
    return mesh;
}

}  // namespace rt
