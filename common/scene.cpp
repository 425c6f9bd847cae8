#include "common/scene.hpp"

#include <algorithm>

namespace rt {

int Scene::drop_unused_lights() {
    const auto before = lights.size();
    lights.erase(std::remove_if(lights.begin(), lights.end(), [](const Light& l) { return l.color == Color(0); }),
                 lights.end());
    return int(before - lights.size());
}

}  // namespace rt
