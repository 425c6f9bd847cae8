#pragma once
// The simple shading models of chapters 01-02: pictures of geometry, not of light.
#include "common/scene.hpp"

namespace rt {

// Maps a unit direction's components from [-1, 1] to [0, 1]: chapter 01's picture of rays.
inline Color direction_color(const Vec3& d) {
    const Vec3 n = glm::normalize(d);
    return Color(0.5f * (Color(n) + 1.0f));
}

// Colour = the ray's direction. No geometry is consulted.
class RayDirectionIntegrator : public Integrator {
public:
    Color Li(const Scene&, const Ray& ray, Sampler&, RayCounters&) const override {
        return direction_color(ray.direction);
    }
};

// Colour = where the ray starts, relative to the eye, in units of `extent` (the view
// window's size): the only thing that varies across an orthographic view.
class RayOriginIntegrator : public Integrator {
public:
    RayOriginIntegrator(Vec3 eye, Real extent) : eye_(eye), extent_(extent) {}
    Color Li(const Scene&, const Ray& ray, Sampler&, RayCounters&) const override {
        return Color(Vec3(0.5) + (ray.origin - eye_) / extent_);
    }

private:
    Vec3 eye_;
    Real extent_;
};

// Colour = the unit normal at the first hit, or the background.
class NormalIntegrator : public Integrator {
public:
    Color Li(const Scene& scene, const Ray& ray, Sampler&, RayCounters&) const override {
        HitRecord rec;
        if (!scene.hit(ray, 0, kInfinity, rec)) return scene.background;
        return Color(0.5f * (Color(rec.normal) + 1.0f));
    }
};

}  // namespace rt
