#pragma once
// Lights of the ray tracing program (course §9.4): at a shading point each gives the
// direction towards it, how far away it is (what a shadow ray needs) and its colour. No
// falloff with distance, as in the course's shading model. A parallelogram light (chapter
// 15, course §9.11.2) is a point light at a random place on it, one per sample: its
// shadows come out soft when the samples are averaged.
#include "core/real.hpp"

namespace rt {

struct LightSample {
    Vec3 direction;  // unit, from the point towards the light
    Real distance;   // to the light along direction; infinite for a directional light
    Color color;     // c_l
};

struct Light {
    enum class Type { point, directional, parallelogram };
    Type type = Type::point;
    Vec3 position{0};           // point lights; a parallelogram's corner
    Vec3 direction{0, -1, 0};   // directional lights: the direction the light travels
    Vec3 edge_a{0}, edge_b{0};  // parallelogram: its two edges from the corner
    Color color{1};             // c_l

    bool is_area() const { return type == Type::parallelogram; }
    // The point light standing at q, with this light's colour: what a sample of an area light is.
    Light at(const Vec3& q) const {
        Light l;
        l.position = q;
        l.color = color;
        return l;
    }

    // The direction and distance to the light from p. An area light is taken at its centre
    // here (shading without shadows, chapter 05's); chapter 15 samples it with at().
    LightSample sample(const Vec3& p) const {
        if (type == Type::directional) return {-unit_vector(direction), kInfinity, color};
        const Vec3 to = (is_area() ? position + Real(0.5) * (edge_a + edge_b) : position) - p;
        const Real distance = glm::length(to);
        if (!(distance > 0)) return {Vec3(0, 0, 1), 0, Color(0)};  // a point on the light: no direction to it
        // Bit for bit what glm::normalize computes: to times 1 / sqrt(to . to).
        return {to * (Real(1) / distance), distance, color};
    }
};

// Exercise 15.2: the point of a parallelogram light at (u, v) in [0, 1)^2: the corner plus
// u along one edge and v along the other. Which edge u takes is yours to choose (u along
// edge_a or along edge_b): the light is the same either way, and the tests accept both.
// Within a few units in the last place (8 epsilons of coordinates up to 8); exactly the
// corner at (0, 0), which every way gives.
Vec3 light_point(const Light& light, const Vec2& uv);

}  // namespace rt
