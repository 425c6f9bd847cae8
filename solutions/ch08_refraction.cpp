// Chapter 08 exercises: refraction (book §8, course §9.7). Declared in
// common/shading/optics.hpp.
#include "core/exercise.hpp"
#include "shading/optics.hpp"

#include <cmath>

namespace rt {

// @book refract
bool refract(const Vec3& d, const Vec3& n, Real n_from, Real n_to, Vec3& t) {
    // @exercise 8.1 | refract | book §8.1
    // cos(phi)^2 = 1 - (n/n_t)^2 (1 - cos(theta)^2); below zero there is no phi.
    const Real cos_theta = -glm::dot(d, n);
    const Real ratio = n_from / n_to;
    const Real cos2_phi = 1 - ratio * ratio * (1 - cos_theta * cos_theta);
    if (cos2_phi < 0) return false;
    t = ratio * (d + n * cos_theta) - n * std::sqrt(cos2_phi);
    return true;
    // @end
}
// @book-end

// @book schlick
Real schlick(Real cosine, Real ior) {
    // @exercise 8.2 | schlick | book §8.2
    const Real r0 = (ior - 1) * (ior - 1) / ((ior + 1) * (ior + 1));
    const Real c = 1 - cosine;
    return r0 + (1 - r0) * c * c * c * c * c;
    // @end
}
// @book-end

// @book beer
Color beer(const Color& attenuation, Real distance) {
    // @exercise 8.3 | beer | book §8.3
    // I(s) = I(0) a^s: e^(s ln a), with the logarithm's sign as it should be (see the errata).
    const float s = float(distance);
    return Color(std::pow(attenuation.r, s), std::pow(attenuation.g, s), std::pow(attenuation.b, s));
    // @end
}
// @book-end

}  // namespace rt
