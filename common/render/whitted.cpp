#include "render/whitted.hpp"

#include "render/scene.hpp"
#include "render/strata.hpp"
#include "shading/optics.hpp"

#include <algorithm>

namespace rt {

bool in_shadow(const Scene& scene, const SpawnedRay& spawned, int light, const Color& light_color,
               TraceContext& context) {
    context.counters.count(RayKind::shadow);
    SpawnedRay s = spawned;
    s.ray.time = context.time;  // what moves is where it is at the camera ray's time
    const bool blocked = scene.occluded(s.ray, s.interval);
    if (context.tree) {  // --pick: say what blocks it, which the any-hit query does not
        TraceContext shadow = context.child(RayKind::shadow, s.interval, light_color, "light colour");
        shadow.open(s.ray);
        context.tree->nodes[std::size_t(shadow.node)].light = light;
        HitRecord rec;
        if (blocked && scene.hit(s.ray, s.interval, rec)) shadow.record_hit(rec);
        context.tree->nodes[std::size_t(shadow.node)].hit = blocked;
        shadow.close(blocked ? Color(0) : Color(1));
    }
    return blocked;
}

Color WhittedIntegrator::shade(const Scene& scene, const Ray& ray, const HitRecord* hit, TraceContext& context) const {
    context.open(ray);
    if (!hit) return context.close(scene.background);
    const HitRecord& rec = *hit;
    context.record_hit(rec);
    const Material& m = scene.material(rec.material);
    // Shade the side the ray arrives on; which side that is, the geometric normal decides.
    const bool front = glm::dot(rec.normal, ray.direction) < 0;
    const ShadePoint sp{{rec.p, front ? rec.normal : -rec.normal, rec.error},
                        front ? rec.shading_normal : -rec.shading_normal,
                        -unit_vector(ray.direction),
                        m.diffuse_at(rec.p),
                        m};
    Color c = sp.diffuse * scene.ambient;
    // A surface with neither a diffuse colour nor a highlight (clear glass, a perfect
    // mirror) takes nothing from the lights: no shadow rays.
    const bool lit = sp.diffuse != Color(0) || m.has_specular();
    for (std::size_t k = 0; lit && k < scene.lights.size(); ++k) {
        ++context.counters.light_terms;
        const Light& light = scene.lights[k];
        // An area light (chapter 15) is a point light at one place on it per sample; a point
        // light draws no sample at all.
        if (light.is_area())
            c += direct_light(scene, light.at(light_point(light, sample_square(context.sampler, Dimension::light))),
                              int(k), sp, context);
        else
            c += direct_light(scene, light, int(k), sp, context);
    }
    if (m.is_dielectric() || m.has_mirror()) {
        if (context.depth >= scene.max_depth) {
            context.note("maximum depth reached: no further rays");
        } else if (m.is_dielectric()) {
            c += dielectric(scene, ray, rec, m, context);
        } else {
            // The mirror direction about the shading normal (smooth meshes reflect smoothly).
            Vec3 r = reflect(ray.direction, sp.n);
            if (m.is_glossy()) {
                // Chapter 17: moved across the glossy square. A ray that ends up below the
                // surface brings nothing back (the energy it stood for is lost: book §17.3).
                r = glossy_direction(unit_vector(r), Real(m.glossy), sample_square(context.sampler, Dimension::glossy));
                if (!(glm::dot(r, sp.side) > 0)) {
                    context.note("glossy direction below the surface: black");
                    return context.close(c);
                }
            }
            c += trace(scene, ray, rec, r, RayKind::reflection, m.mirror, "mirror colour", context);
        }
    }
    return context.close(c);
}

Color WhittedIntegrator::trace(const Scene& scene, const Ray& ray, const HitRecord& rec, const Vec3& direction,
                               RayKind kind, const Color& weight, const char* why, TraceContext& context) const {
    // Leave on the side the new ray goes to: outside for a reflection, inside for a refraction.
    const Vec3 side = glm::dot(direction, rec.normal) >= 0 ? rec.normal : -rec.normal;
    const SpawnedRay s = spawn_ray({rec.p, side, rec.error}, direction, kInfinity, scene.offset, ray.time);
    TraceContext child = context.child(kind, s.interval, weight, why);
    if (!(child.reach > 0)) return Color(0);
    if (child.reach < scene.min_reach) {
        context.note("a ray that would carry under the scene's min_reach of the pixel was not cast");
        return Color(0);
    }
    context.counters.count(kind);
    return weight * Li(scene, s.ray, child);
}

Color WhittedIntegrator::dielectric(const Scene& scene, const Ray& ray, const HitRecord& rec, const Material& m,
                                    TraceContext& context) const {
    // Course §9.7: normals point out into the air, so d . n < 0 means the ray is entering.
    const Vec3 d = unit_vector(ray.direction);
    const bool entering = glm::dot(d, rec.normal) < 0;
    // Refract about the shading normal unless it disagrees with the geometric one about
    // which side the ray is on (near a smooth mesh's silhouette): then the geometric one.
    const Vec3 n = (glm::dot(d, rec.shading_normal) < 0) == entering ? rec.shading_normal : rec.normal;
    const Vec3 r = reflect(d, n);
    const Real ior = Real(m.ior);
    Color k(1);  // Beer's law, for a ray that has travelled inside
    Vec3 t;
    bool transmitted;
    if (entering) {
        transmitted = refract(d, n, 1, ior, t);
    } else {
        // The ray's t measures in units of its direction's length (course §9.8's convention).
        if (m.absorbs()) k = beer(m.attenuation, rec.t * glm::length(ray.direction));
        transmitted = refract(d, -n, ior, 1, t);
    }
    const bool beer_applies = k != Color(1);
    if (!transmitted) {
        context.note("total internal reflection: no refracted ray");
        return trace(scene, ray, rec, r, RayKind::reflection, k, beer_applies ? "Beer" : "total internal reflection",
                     context);
    }
    // Schlick takes the cosine on the air side, which is the larger angle: the smaller cosine.
    const Real cosine = std::min(std::abs(glm::dot(d, n)), std::abs(glm::dot(t, n)));
    const Real R = schlick(cosine, ior);
    const Color reflected = trace(scene, ray, rec, r, RayKind::reflection, k * float(R),
                                  beer_applies ? "Beer x Schlick R" : "Schlick R", context);
    return reflected + trace(scene, ray, rec, t, RayKind::refraction, k * float(1 - R),
                             beer_applies ? "Beer x (1 - R)" : "1 - R", context);
}

}  // namespace rt
