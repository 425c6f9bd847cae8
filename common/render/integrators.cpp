#include "render/integrators.hpp"

#include "render/whitted.hpp"

namespace rt {

std::shared_ptr<const Integrator> make_integrator(const std::string& name) {
    if (name == "phong") return std::make_shared<PhongIntegrator>();
    if (name == "whitted") return std::make_shared<WhittedIntegrator>();
    if (name == "normal") return std::make_shared<NormalIntegrator>();
    if (name == "barycentric") return std::make_shared<BarycentricIntegrator>();
    if (name == "direction") return std::make_shared<RayDirectionIntegrator>();
    return nullptr;
}

}  // namespace rt
