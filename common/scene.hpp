#pragma once
#include "common/camera.hpp"
#include "common/counters.hpp"
#include "common/light.hpp"
#include "common/material.hpp"
#include "common/sampler.hpp"
#include "common/surface.hpp"

#include <memory>
#include <string>
#include <vector>

namespace rt {

struct Scene;

// Turns a viewing ray into a colour. Each chapter's shading model is one of these; the
// render loop does not know which.
class Integrator {
public:
    virtual ~Integrator() = default;
    virtual Color Li(const Scene& scene, const Ray& ray, Sampler& sampler, RayCounters& counters) const = 0;
};

struct Scene {
    std::string name;
    std::string description;
    Camera camera;
    std::shared_ptr<const Surface> world;  // null: nothing to hit
    Color background{0};
    std::shared_ptr<const Integrator> integrator;
    Color ambient{0};           // c_a: ambient light, seen by every surface's diffuse colour
    std::vector<Light> lights;  // only lights that can contribute: see drop_unused()

    // What a scene does not use costs nothing per ray: lights that are black are removed
    // here, once, instead of being looked at for every shading point. Returns how many.
    int drop_unused_lights();

    bool hit(const Ray& ray, Real t0, Real t1, HitRecord& rec) const {
        return world && world->hit(ray, t0, t1, rec);
    }
};

}  // namespace rt
