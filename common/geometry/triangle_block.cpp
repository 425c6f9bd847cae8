#include "geometry/triangle_block.hpp"

#include "core/float_round.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

namespace {

// The axes in the order kx, ky, kz for each main axis kz and sign of d[kz], as exercise 3.2
// chooses them: kx and ky follow kz around, swapped where d[kz] < 0.
constexpr int kAxes[3][2][3] = {{{1, 2, 0}, {2, 1, 0}}, {{2, 0, 1}, {0, 2, 1}}, {{0, 1, 2}, {1, 0, 2}}};

}  // namespace

RayShear::RayShear(const Ray& ray, const Vec3& inv_direction) {
    // Plain arrays: glm's operator[] with an index known only at run time is a switch.
    const Real d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
    const Real o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    const Real inv[3] = {inv_direction.x, inv_direction.y, inv_direction.z};
    const Real ax = std::abs(d[0]), ay = std::abs(d[1]), az = std::abs(d[2]);
    const int kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
    const int* k = kAxes[kz][d[kz] < 0];
    // Exercise 3.2 divides; a product with 1/d is one rounding in Real away from its quotient,
    // which the filter's margins cover (E counts 16 float roundings, the shear needs ~11).
    sx = float(d[k[0]] * inv[kz]);
    sy = float(d[k[1]] * inv[kz]);
    sz = float(inv[kz]);
    for (int i = 0; i < 3; ++i) {
        origin[i] = float(o[k[i]]);
        offset[i] = std::size_t(k[i]) * sizeof(float[4]);
    }
    origin_size = float_above(std::max({std::abs(o[0]), std::abs(o[1]), std::abs(o[2])}));
}

[[gnu::noinline]] bool blocks_ray_exactly(unsigned lanes, const TriangleBlock& block,
                                          const std::array<Vec3, 3>* corners, const Ray& ray, Interval interval) {
    return exact_hits(lanes, block, corners, ray, interval,
                      [](std::uint32_t, const TriangleHit&, const std::array<Vec3, 3>&) { return true; });
}

TriangleBlock pack(std::span<const std::uint32_t> triangles, const Vec3* positions,
                   const std::array<std::uint32_t, 3>* corners) {
    TriangleBlock block;
    block.count = std::uint32_t(triangles.size());
    block.exact = true;
    for (int lane = 0; lane < 4; ++lane) {
        // Unused lanes repeat the first triangle: finite values, masked off by count.
        const std::uint32_t t = triangles[std::size_t(lane) < triangles.size() ? std::size_t(lane) : 0];
        block.index[lane] = t;
        Real size = 0;
        for (int v = 0; v < 3; ++v)
            for (int a = 0; a < 3; ++a) {
                const Real c = positions[corners[t][std::size_t(v)]][a];
                block.p[v][a][lane] = float(c);
                block.exact = block.exact && round_to_float(c) == c;
                size = std::max(size, std::abs(c));
            }
        block.size[lane] = float_above(size);
    }
    return block;
}

}  // namespace rt
