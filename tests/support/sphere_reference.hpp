#pragma once
// What the accuracy tests of ray-sphere roots share (chapter 02's graded tests of exercise
// 2.2, and the common program's evidence against the textbook form): a long-double
// reference and rays at a far sphere's silhouette.
#include "core/ray.hpp"

#include <pcg_random.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace rt::test {

// The reference: both roots of the same (Real) inputs in long double, with the stable
// formulas so that the reference itself loses nothing to cancellation.
inline bool reference_roots(const Ray& r, const Vec3& c, Real R, long double& t_near, long double& t_far) {
    using LVec = glm::vec<3, long double>;
    const LVec d(r.direction), f = LVec(r.origin) - LVec(c);
    const long double a = glm::dot(d, d), b = glm::dot(f, d), rr = (long double)R;
    const LVec foot = f - (b / a) * d;
    const long double h = std::sqrt(glm::dot(foot, foot));
    const long double disc = a * (rr - h) * (rr + h);
    if (disc < 0) return false;
    const long double q = -(b + std::copysign(std::sqrt(disc), b));
    const long double cc = glm::dot(f, f) - rr * rr;
    t_near = std::min(q / a, cc / q);
    t_far = std::max(q / a, cc / q);
    return true;
}

// Rays from the origin at a unit sphere `distance` radii away, aimed at points spread
// uniformly over `fraction` of its silhouette disk.
template <class F>
void far_sphere_rays(Real distance, Real fraction, int count, F&& f) {
    pcg32 rng(7);
    std::uniform_real_distribution<double> unit(0, 1);
    const Vec3 c = glm::normalize(Vec3(0.6, 0.3, -0.74)) * distance;
    const Vec3 ahead = glm::normalize(c);
    const Vec3 side = glm::normalize(glm::cross(ahead, Vec3(0, 1, 0)));
    const Vec3 up = glm::cross(side, ahead);
    for (int k = 0; k < count; ++k) {
        const double radius = fraction * std::sqrt(unit(rng)), phi = 2 * std::numbers::pi * unit(rng);
        const Vec3 target = c + Real(radius * std::cos(phi)) * side + Real(radius * std::sin(phi)) * up;
        f(Ray{Vec3(0), target}, c);
    }
}

}  // namespace rt::test
