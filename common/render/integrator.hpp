#pragma once
// An integrator turns a ray into a colour: each chapter's shading model is one, and the
// render loop does not know which.
#include "core/counters.hpp"
#include "core/ray.hpp"
#include "core/sampler.hpp"

namespace rt {

struct Scene;

// What travels with every integrator call: the pixel's random numbers, the counters, and
// where in the ray tree this ray is. Recursive chapters (reflection, refraction) call
// Li again with child(kind); nothing else needs a new parameter.
struct TraceContext {
    Sampler& sampler;
    RayCounters& counters;
    int depth = 0;                   // 0 for a camera ray, +1 per bounce
    RayKind kind = RayKind::camera;  // why this ray was cast

    TraceContext child(RayKind k) const { return TraceContext{sampler, counters, depth + 1, k}; }
};

class Integrator {
public:
    virtual ~Integrator() = default;
    virtual Color Li(const Scene& scene, const Ray& ray, TraceContext& context) const = 0;
};

}  // namespace rt
