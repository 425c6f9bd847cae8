#pragma once
// A big ground (tests of chapters 06 and 09): the cover of Ray Tracing in One Weekend stands
// on a sphere of radius 1000 centred 1000 below the origin. Its hit points near the origin
// have small coordinates but the rounding of numbers near 1000 (book §6.3), which
// offset_origin's step alone does not clear: shadow rays that leave them outwards, and so
// cannot meet the ground again, do (acne) unless the spawn clears the hit's error bound.
#include "render/scene.hpp"

#include <cmath>

namespace rt::test {

// The ground of `scene`, hit from above at a 21 x 21 grid of points within 45 units of the
// origin, each lit from 32 directions of every side and height (2 to 62 degrees above the
// horizon). `visit(rec, to_light)` sees each hit and each unit direction to a light that the
// hit's normal faces.
template <class Visit>
void big_ground_hits(const Scene& scene, Visit visit) {
    for (int i = -10; i <= 10; ++i)
        for (int k = -10; k <= 10; ++k) {
            const Ray down{Vec3(Real(2.9) * Real(i), 5, Real(3.1) * Real(k)), Vec3(Real(0.05), -1, Real(0.02))};
            HitRecord rec;
            if (!scene.hit(down, Interval{}, rec)) continue;
            for (int l = 0; l < 32; ++l) {
                const Real azimuth = Real(0.196) * Real(l), elevation = Real(0.035) + Real(0.034) * Real(l % 31);
                const Vec3 to_light(std::cos(elevation) * std::cos(azimuth), std::sin(elevation),
                                    std::cos(elevation) * std::sin(azimuth));
                if (glm::dot(to_light, rec.normal) > 0) visit(rec, to_light);
            }
        }
}

// How many of big_ground_hits' shadow rays, spawned clearing `error(rec)`, find the ground.
struct SelfShadow {
    long rays = 0;
    long acne = 0;
};
template <class Error>
SelfShadow self_shadow(const Scene& scene, Error error) {
    SelfShadow count;
    big_ground_hits(scene, [&](const HitRecord& rec, const Vec3& to_light) {
        const SpawnedRay s = spawn_ray({rec.p, rec.normal, error(rec)}, to_light, kInfinity, Offset{});
        ++count.rays;
        count.acne += scene.occluded(s.ray, s.interval);
    });
    return count;
}

}  // namespace rt::test
