#pragma once
// Lights of the ray tracing program (§9.4): each gives, at a shading point, the direction
// towards it and its colour. No falloff with distance, as in the course's shading model.
#include "common/real.hpp"

namespace rt {

struct Light {
    enum class Type { point, directional };
    Type type = Type::point;
    Vec3 position{0};            // point lights
    Vec3 direction{0, -1, 0};    // directional lights: the direction the light travels
    Color color{1};              // c_l

    // Unit vector from p towards the light.
    Vec3 to_light(const Vec3& p) const {
        return type == Type::point ? glm::normalize(position - p) : -glm::normalize(direction);
    }
};

}  // namespace rt
