#pragma once
// The recursive ray tracer of course §9.5-9.7 (Whitted's): Blinn-Phong shading with a
// shadow ray per light (chapter 06), perfect mirrors (07) and dielectrics (08). A material
// that is not a mirror or a dielectric casts no secondary ray at all, and a scene without
// such materials renders exactly as chapter 06's shadows alone.
#include "core/offset.hpp"
#include "render/first_hit.hpp"
#include "shading/light.hpp"
#include "shading/material.hpp"

namespace rt {

// A hit, turned towards the viewer and ready to shade. Its SurfacePoint part (core/offset.hpp)
// is where shadow rays leave from: `p`, the hit point; `side`, the unit geometric normal on
// the viewer's side; `error`, how far p may lie off the surface (HitRecord::error). So
// spawn_ray(sp, ...) takes all three, and the bound cannot be left behind.
struct ShadePoint : SurfacePoint {
    Vec3 n;         // unit shading normal on the same side: what the shading terms use
    Vec3 v;         // unit, towards the viewer
    Color diffuse;  // the material's diffuse colour at p
    const Material& material;
};

// Casts the shadow ray `s` towards light number `light` of the scene (any-hit, counted as a
// shadow ray, recorded in the ray tree when there is one). True if something blocks it.
bool in_shadow(const Scene& scene, const SpawnedRay& s, int light, const Color& light_color, TraceContext& context);

// Exercise 6.2: what one light adds at a shade point: Lambert plus the Blinn-Phong highlight
// (chapter 05), or nothing if the point is in shadow. Casts no shadow ray when the light
// cannot add anything anyway: it is black, or behind the surface.
Color direct_light(const Scene& scene, const Light& light, int light_index, const ShadePoint& sp,
                   TraceContext& context);

class WhittedIntegrator : public FirstHitIntegrator<WhittedIntegrator> {
public:
    // What a ray brings back from its first hit (null: it hit nothing).
    Color shade(const Scene& scene, const Ray& ray, const HitRecord* hit, TraceContext& context) const;

private:
    // Casts a secondary ray from the hit in `direction`, and returns its colour times
    // `weight`; nothing at all when the weight is black.
    Color trace(const Scene& scene, const Ray& ray, const HitRecord& rec, const Vec3& direction, RayKind kind,
                const Color& weight, const char* why, TraceContext& context) const;
    Color dielectric(const Scene& scene, const Ray& ray, const HitRecord& rec, const Material& m,
                     TraceContext& context) const;
};

}  // namespace rt
