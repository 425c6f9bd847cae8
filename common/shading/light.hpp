#pragma once
// Lights of the ray tracing program (course §9.4): at a shading point each gives the
// direction towards it, how far away it is (what a shadow ray needs) and its colour. No
// falloff with distance, as in the course's shading model.
#include "core/real.hpp"

namespace rt {

struct LightSample {
    Vec3 direction;  // unit, from the point towards the light
    Real distance;   // to the light along direction; infinite for a directional light
    Color color;     // c_l
};

struct Light {
    enum class Type { point, directional };
    Type type = Type::point;
    Vec3 position{0};          // point lights
    Vec3 direction{0, -1, 0};  // directional lights: the direction the light travels
    Color color{1};            // c_l

    LightSample sample(const Vec3& p) const {
        if (type == Type::directional) return {-unit_vector(direction), kInfinity, color};
        const Vec3 to = position - p;
        const Real distance = glm::length(to);
        if (!(distance > 0)) return {Vec3(0, 0, 1), 0, Color(0)};  // a point on the light: no direction to it
        // Bit for bit what glm::normalize computes: to times 1 / sqrt(to . to).
        return {to * (Real(1) / distance), distance, color};
    }
};

}  // namespace rt
