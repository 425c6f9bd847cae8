#include "geometry/triangle_block.hpp"

#include "core/float_round.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace rt {

RayShear::RayShear(const Ray& ray, const Vec3& inv_direction) {
    const Vec3& d = ray.direction;
    const Vec3 ad = glm::abs(d);
    kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    if (d[kz] < 0) std::swap(kx, ky);
    // Exercise 3.2 divides; a product with 1/d is one rounding in Real away from its quotient,
    // which the filter's margins cover (E counts 16 float roundings, the shear needs ~11).
    sx = float(d[kx] * inv_direction[kz]);
    sy = float(d[ky] * inv_direction[kz]);
    sz = float(inv_direction[kz]);
    for (int a = 0; a < 3; ++a) origin[a] = float(ray.origin[a]);
    const Vec3 ao = glm::abs(ray.origin);
    origin_size = float_above(std::max({ao.x, ao.y, ao.z}));
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
