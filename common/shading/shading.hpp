#pragma once
// The shading terms of the ray tracing program (book §5, course §9.4, with the lighting model of the
// course's chapter 8). lambert and blinn_phong_highlight are chapter 05 exercises.
#include "core/real.hpp"

namespace rt {

// Both are graded within float's rounding (a relative 1e-5), and exactly 0 where they give
// nothing: any order of the products passes.

// Exercise 5.2: diffuse light from one light, c_r c_l max(0, n . l). n and l unit length.
Color lambert(const Color& diffuse, const Color& light, const Vec3& n, const Vec3& l);

// Exercise 5.3: the Blinn-Phong highlight from one light, c_l c_p max(0, n . h)^p with h the
// unit half vector between l and v (towards the light and towards the eye, both unit). No
// highlight from a light behind the surface (n . l < 0), even where h tips to n's side; a
// light exactly in the surface's plane (n . l = 0) may give either.
Color blinn_phong_highlight(const Color& specular, float exponent, const Color& light, const Vec3& n, const Vec3& l,
                            const Vec3& v);

}  // namespace rt
