#pragma once
// What surfaces are made of (course §9.4.1's `material`): plain data in one closed set.
// Every material is this one struct; a kind a later chapter adds (mirror, dielectric,
// glossy) is more fields here, black or zero when unused, so the renderer can skip what a
// material does not have and a surface refers to its material by a small index.
#include "core/real.hpp"

namespace rt {

struct Material {
    Color diffuse{0.7f};  // c_r: Lambertian reflectance, also what ambient light sees
    Color specular{0};    // c_p: Blinn-Phong highlight colour; black = no highlight term at all
    float exponent = 32;  // p: highlight sharpness

    bool has_specular() const { return specular != Color(0); }
};

}  // namespace rt
