#pragma once
// The optics of perfect mirrors and dielectrics (book §7-8, course §9.6-9.7). All four are
// exercises: reflect in chapter 07, the others in chapter 08.
#include "core/real.hpp"

namespace rt {

// Exercise 7.1: the mirror direction of d about the unit normal n, r = d - 2 (d . n) n. As
// in the course, d points towards the surface (it is a ray's direction) and r away from it;
// r has d's length, and either side of n works. Graded within 8 machine epsilons on random
// vectors (16 for reflecting twice), exactly where every number is exact (normals along an
// axis): any arrangement of the formula passes, glm::reflect's too.
Vec3 reflect(const Vec3& d, const Vec3& n);

// Exercises 8.1-8.3 are graded within rounding, never by their bits (8.1: Snell's law to
// 10^3 machine epsilons, unit length to 10^2; the rest to float's 10^-5), and exactly only
// where every way is exact: beer() at distance 0 is 1.

// Exercise 8.1: Snell's law through the cosines (course §9.7). d is unit and points towards
// the surface; n is the unit normal on the side d comes from (d . n <= 0); the ray passes
// from index n_from into index n_to. True and `t` the unit transmitted direction, or false
// on total internal reflection, when no ray is transmitted.
bool refract(const Vec3& d, const Vec3& n, Real n_from, Real n_to, Vec3& t);

// Exercise 8.2: Schlick's approximation of the Fresnel reflectance for a dielectric of index
// `ior` in air, R0 + (1 - R0)(1 - cos)^5 with R0 = ((ior - 1)/(ior + 1))^2. `cosine` is the
// cosine of the angle on the air side, whichever way the ray goes.
Real schlick(Real cosine, Real ior);

// Exercise 8.3: Beer's law: what remains of each channel after `distance` inside a medium
// that leaves `attenuation` of it after one unit, attenuation^distance.
Color beer(const Color& attenuation, Real distance);

// Exercise 17.1: a glossy reflection direction (course §9.11.4): the unit mirror direction r
// moved across a square of width `width` centred on it, square to r, to the place uv in
// [0, 1)^2 of that square: r + (u - 1/2) width U + (v - 1/2) width V. The frame is the
// course's (and the tests check it): U = normalize(e x r), where e is the axis along which r
// has its smallest component in size (x on ties, then y), and V = r x U. Not unit length; it
// may point below the surface (the caller checks).
Vec3 glossy_direction(const Vec3& r, Real width, const Vec2& uv);

}  // namespace rt
