#pragma once
// The shading models: pictures of geometry (chapters 01-04), then of light (05).
#include "render/first_hit.hpp"
#include "render/scene.hpp"
#include "shading/shading.hpp"

#include "core/names.hpp"

#include <cstdint>
#include <memory>

namespace rt {

// Maps a unit direction's components from [-1, 1] to [0, 1]: chapter 01's picture of rays,
// and of normals.
inline Color direction_color(const Vec3& d) {
    const Vec3 n = glm::normalize(d);
    return Color(0.5f * (Color(n) + 1.0f));
}

// Colour = the ray's direction. No geometry is consulted.
class RayDirectionIntegrator : public IntegratorOf<RayDirectionIntegrator> {
public:
    Color Li(const Scene&, const Ray& ray, TraceContext&) const override { return direction_color(ray.direction); }
};

// Colour = where the ray starts, relative to the eye, in units of `extent` (the view
// window's size): the only thing that varies across an orthographic view.
class RayOriginIntegrator : public IntegratorOf<RayOriginIntegrator> {
public:
    RayOriginIntegrator(Vec3 eye, Real extent) : eye_(eye), extent_(extent) {}
    Color Li(const Scene&, const Ray& ray, TraceContext&) const override {
        return Color(Vec3(0.5) + (ray.origin - eye_) / extent_);
    }

private:
    Vec3 eye_;
    Real extent_;
};

// Colour = the unit normal at the first hit, or the background.
class NormalIntegrator : public FirstHitIntegrator<NormalIntegrator> {
public:
    Color shade(const Scene& scene, const Ray&, const HitRecord* rec, TraceContext&) const {
        if (!rec) return scene.background;
        return Color(0.5f * (Color(rec->normal) + 1.0f));
    }
};

// Colour = the barycentric coordinates (1 - beta - gamma, beta, gamma) of a triangle hit;
// other surfaces show their normal.
class BarycentricIntegrator : public FirstHitIntegrator<BarycentricIntegrator> {
public:
    Color shade(const Scene& scene, const Ray&, const HitRecord* rec, TraceContext&) const {
        if (!rec) return scene.background;
        if (!rec->has_barycentrics) return Color(0.5f * (Color(rec->normal) + 1.0f));
        return Color(float(1 - rec->beta - rec->gamma), float(rec->beta), float(rec->gamma));
    }
};

// Colour = what finding the first hit cost (book §10.6): boxes plus primitives tested for
// the camera ray, on a heat scale from black (nothing) through blue and red to yellow at
// `full` tests and beyond. Pictures where a structure spends its time.
class CostIntegrator : public IntegratorOf<CostIntegrator> {
public:
    explicit CostIntegrator(float full = 256) : full_(full) {}
    Color Li(const Scene& scene, const Ray& ray, TraceContext&) const override;

private:
    float full_;
};

// The ray tracing program of course §9.4: ambient + Lambert + Blinn-Phong for every light,
// no shadows yet. Highlights are computed only for materials that have a specular colour.
class PhongIntegrator : public FirstHitIntegrator<PhongIntegrator> {
public:
    Color shade(const Scene& scene, const Ray& ray, const HitRecord* rec, TraceContext& context) const {
        if (!rec) return scene.background;
        const Material& m = scene.material(rec->material);
        // Shade the side the eye sees: flip the normal of a surface seen from behind.
        const Vec3 n = glm::dot(rec->normal, ray.direction) < 0 ? rec->normal : -rec->normal;
        const Vec3 v = -glm::normalize(ray.direction);
        Color c = m.diffuse * scene.ambient;
        for (const Light& light : scene.lights) {
            const LightSample l = light.sample(rec->p);
            ++context.counters.light_terms;
            c += lambert(m.diffuse, l.color, n, l.direction);
            if (m.has_specular()) {
                ++context.counters.specular_terms;
                c += blinn_phong_highlight(m.specular, m.exponent, l.color, n, l.direction, v);
            }
        }
        return c;
    }
};

// The integrators a scene file can name ("shading"): whitted is render/whitted.hpp, cost
// the CostIntegrator above.
enum class Shading : std::uint8_t { phong, whitted, normal, barycentric, direction, cost };
inline constexpr auto kShadingNames =
    names_of<Shading>({"phong", "whitted", "normal", "barycentric", "direction", "cost"});
std::shared_ptr<const Integrator> make_integrator(Shading shading);

}  // namespace rt
