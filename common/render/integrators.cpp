#include "render/integrators.hpp"

#include "core/traversal_count.hpp"
#include "render/whitted.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

Color CostIntegrator::Li(const Scene& scene, const Ray& ray, TraceContext&) const {
    const TraversalCount before = traversal_tally;
    HitRecord rec;
    (void)scene.hit(ray, Interval{}, rec);
    const auto tests = float(traversal_tally.nodes - before.nodes + traversal_tally.items - before.items);
    // On a square-root scale, so that cheap rays still differ: black, blue, red, yellow.
    const float x = std::min(1.0f, std::sqrt(tests / full_));
    const Color stops[] = {Color(0), Color(0.1f, 0.2f, 0.9f), Color(0.9f, 0.15f, 0.1f), Color(1, 0.95f, 0.3f)};
    const float at = x * 3;
    const int k = std::min(2, int(at));
    return glm::mix(stops[k], stops[k + 1], at - float(k));
}

std::shared_ptr<const Integrator> make_integrator(Shading shading) {
    switch (shading) {  // no default: a new kind of shading without an integrator is warned about
        case Shading::phong:
            return std::make_shared<PhongIntegrator>();
        case Shading::whitted:
            return std::make_shared<WhittedIntegrator>();
        case Shading::normal:
            return std::make_shared<NormalIntegrator>();
        case Shading::barycentric:
            return std::make_shared<BarycentricIntegrator>();
        case Shading::direction:
            return std::make_shared<RayDirectionIntegrator>();
        case Shading::cost:
            return std::make_shared<CostIntegrator>();
    }
    return nullptr;
}

}  // namespace rt
