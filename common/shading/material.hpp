#pragma once
// What surfaces are made of (course §9.4.1's `material`): plain data in one closed set.
// Every material is this one struct; a kind a later chapter adds (mirror, dielectric,
// glossy) is more fields here, black or zero when unused, so the renderer can skip what a
// material does not have and a surface refers to its material by a small index.
#include "core/real.hpp"

#include <cmath>

namespace rt {

struct Material {
    Color diffuse{0.7f};  // c_r: Lambertian reflectance, also what ambient light sees
    Color specular{0};    // c_p: Blinn-Phong highlight colour; black = no highlight term at all
    float exponent = 32;  // p: highlight sharpness
    // A checkerboard in x and z (a floor's plane; book §7.4): squares of side checker_size
    // alternate between `diffuse` and `checker`. 0 = plain. Not in y: a floor at y = 0 would
    // sit exactly on a boundary, and rounding would pick its colour at random.
    Color checker{0};
    float checker_size = 0;
    // Chapter 07: c_s, how much of what the mirror direction sees is reflected (course §9.6).
    // Black = not a mirror, and no reflection ray is ever cast.
    Color mirror{0};
    // Chapter 17: a glossy mirror blurs its reflection: each reflection ray leaves in the
    // mirror direction moved across a square of this width (course §9.11.4). 0 = sharp, and
    // no glossy sample is ever drawn.
    float glossy = 0;
    // Chapter 08: a dielectric (glass, water) has an index of refraction; 0 = opaque, and no
    // refraction ray is ever cast. `attenuation` is Beer's law's a: the share of each
    // channel left after one unit of distance inside (course §9.7).
    float ior = 0;
    Color attenuation{1};

    bool has_specular() const { return specular != Color(0); }
    bool has_mirror() const { return mirror != Color(0); }
    bool is_glossy() const { return glossy > 0; }
    bool is_dielectric() const { return ior > 0; }
    bool absorbs() const { return attenuation != Color(1); }

    // The diffuse colour at point p (object or world space, as the caller decides).
    Color diffuse_at(const Vec3& p) const {
        if (!(checker_size > 0)) return diffuse;
        const Vec3 q = p / Real(checker_size);
        const auto cell = std::floor(q.x) + std::floor(q.z);
        return std::fmod(std::abs(cell), 2.0) < 1 ? diffuse : checker;
    }
};

}  // namespace rt
