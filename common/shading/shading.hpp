#pragma once
// The shading terms of the ray tracing program (book §5, course §9.4, with the lighting model of the
// course's chapter 8). lambert and blinn_phong_highlight are chapter 05 exercises.
#include "core/real.hpp"

namespace rt {

// Exercise 5.2: diffuse light from one light, c_r c_l max(0, n . l). n and l unit length.
Color lambert(const Color& diffuse, const Color& light, const Vec3& n, const Vec3& l);

// Exercise 5.3: the Blinn-Phong highlight from one light, c_l c_p max(0, n . h)^p with h the
// unit half vector between l and v (towards the light and towards the eye, both unit).
Color blinn_phong_highlight(const Color& specular, float exponent, const Color& light, const Vec3& n, const Vec3& l,
                            const Vec3& v);

}  // namespace rt
