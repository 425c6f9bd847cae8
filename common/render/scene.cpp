#include "render/scene.hpp"

#include <algorithm>

namespace rt {

int Scene::drop_unused_lights() {
    const auto before = lights.size();
    lights.erase(std::remove_if(lights.begin(), lights.end(), [](const Light& l) { return l.color == Color(0); }),
                 lights.end());
    return int(before - lights.size());
}

Scene look_at(const Vec3& eye, const Vec3& target, Real vertical_fov_degrees,
              std::shared_ptr<const Integrator> integrator) {
    Scene s;
    s.camera.eye = eye;
    s.camera.target = target;
    s.camera.vertical_fov_degrees = vertical_fov_degrees;
    s.background = kPictureBackground;
    s.integrator = std::move(integrator);
    return s;
}

}  // namespace rt
