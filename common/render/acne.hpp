#pragma once
// Shadow acne, measured (book §6.4): a stress scene that can be moved away from the origin
// and scaled, and a count of the pixels each offset method wrongly puts in their own
// shadow. Chapter 06 renders the scene; its tests and bench/acne.cpp count.
#include "render/scene.hpp"

#include <cstdint>

namespace rt {

// A ground, a sphere and an icosphere mesh under a low directional light, seen by a
// perspective camera: all of it scaled by `scale` and moved to about `scale` units from the
// origin, so coordinates and their rounding grow together. Shaded by chapter 06's
// integrator with the given offset.
Scene acne_scene(Real scale, const Offset& offset);

struct AcneCount {
    std::uint64_t lit = 0;    // pixels on a surface turned towards the light
    std::uint64_t acne = 0;   // of those, reported in shadow with nothing else in the way
    std::uint64_t leaks = 0;  // in the shadow of another surface, yet reported lit (an offset so large it skips it)
};

// Casts each pixel centre's camera ray and its shadow ray towards the scene's first light,
// with the scene's offset, and compares with the truth: whether a surface other than the
// one hit blocks the light. Every surface of the scene must be convex, so that nothing can
// shadow itself where it faces the light.
AcneCount count_acne(const Scene& scene, int width, int height);

}  // namespace rt
