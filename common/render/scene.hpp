#pragma once
#include "render/antialiasing.hpp"
// Everything a render needs: what is seen (surfaces, materials, lights), from where
// (camera) and how it is shaded (integrator).
#include "accel/accel.hpp"
#include "core/offset.hpp"
#include "render/camera.hpp"
#include "render/integrator.hpp"
#include "shading/light.hpp"
#include "shading/material.hpp"

#include <memory>
#include <span>
#include <string>
#include <vector>

namespace rt {

struct Scene {
    std::string name;
    std::string description;
    Camera camera;
    SurfaceList surfaces;
    std::vector<Material> materials{Material{}};  // materials[0]: the default, for surfaces given none
    std::vector<Light> lights;                    // only lights that can contribute: see drop_unused_lights()
    Color background{0};
    Color ambient{0};  // c_a: ambient light, seen by every surface's diffuse colour
    std::shared_ptr<const Integrator> integrator;
    // Recursive integrators (chapters 07-08): how many bounces a camera ray may start, and
    // how secondary rays leave a surface (chapter 06).
    int max_depth = 5;
    Offset offset;
    // The search structure (book §10.6): what the scene file asks for, and once built (by
    // build_accel(), after the last surface is added), the structure itself. Until then the
    // queries search the list (exercise 5.1).
    AccelKind accel_kind = AccelKind::fast;
    std::shared_ptr<const Accel> accel;
    // A secondary ray that would carry less than this share of its pixel is not cast. Each
    // glass hit splits a ray in two whose weights add up to at most its own, so a camera
    // ray's tree has at most 1 / min_reach ends, and (max_depth + 1) / min_reach rays: a
    // chain of single rays of weight 1 (a perfect mirror, total internal reflection) still
    // runs to max_depth (book §8.4).
    float min_reach = 1.0f / 1024;
    // Antialiasing (book §14): the pattern and filter of the pixel samples, and how many a
    // pixel takes (0: as the command line says, 1 by default). --pattern, --filter and --spp
    // override them.
    Antialiasing antialiasing;
    int samples = 0;

    MaterialId add_material(const Material& m) {
        materials.push_back(m);
        return MaterialId(materials.size() - 1);
    }
    const Material& material(MaterialId id) const { return materials[id]; }

    // What a scene does not use costs nothing per ray: lights that are black are removed
    // here, once, instead of being looked at for every shading point. Returns how many.
    int drop_unused_lights();

    // Builds the search structure of `kind` over the surfaces (replacing any earlier one).
    void build_accel(AccelKind kind) {
        accel_kind = kind;
        accel = std::make_shared<const Accel>(surfaces, kind);
    }

    // The two queries every integrator asks: the closest hit, and whether anything at all is
    // in the way (shadow rays).
    bool hit(const Ray& ray, Interval interval, HitRecord& rec) const {
        if (accel) return accel->hit(surfaces, ray, interval, rec);
        // One surface needs no search. This also keeps the pictures of chapters 02 and 03
        // (one shape each) from depending on exercise 5.1, the search over a list.
        if (surfaces.size() == 1) return surfaces[0].hit(ray, interval, rec);
        return surfaces.hit(ray, interval, rec);
    }
    // The closest hits of up to eight rays from one point, a pinhole camera's: recs[k], and
    // bit k of the answer, for ray k, each exactly what hit() finds (book §10.5).
    unsigned hit_packet(std::span<const Ray> rays, Interval interval, HitRecord* recs) const {
        if (accel) return accel->hit_packet(surfaces, rays, interval, recs);
        return one_by_one(rays.size(), [&](std::size_t k) { return hit(rays[k], interval, recs[k]); });
    }
    bool occluded(const Ray& ray, Interval interval) const {
        if (accel) return accel->occluded(surfaces, ray, interval);
        return surfaces.occluded(ray, interval);
    }
};

// The dark grey behind the pictures of geometry (chapters 02-04): not black, so a black
// surface would still show.
inline const Color kPictureBackground{0.1f, 0.1f, 0.12f};

// A scene seen from `eye` towards `target` with a perspective camera of the given vertical
// field of view, shaded by `integrator`, against the picture background; no surfaces yet.
Scene look_at(const Vec3& eye, const Vec3& target, Real vertical_fov_degrees,
              std::shared_ptr<const Integrator> integrator);

}  // namespace rt
