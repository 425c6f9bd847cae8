#pragma once
// Surface appearance for Blinn-Phong shading (§9.4.1's `material` class).
#include "common/real.hpp"

#include <string>

namespace rt {

struct Material {
    std::string name;
    Color diffuse{0.7f};  // c_r: Lambertian reflectance, also what ambient light sees
    Color specular{0};    // c_p: Blinn-Phong highlight colour; black = no highlight term at all
    float exponent = 32;  // p: highlight sharpness

    bool has_specular() const { return specular != Color(0); }
};

}  // namespace rt
