// Chapter 06 exercises: shadows (book §6, course §9.5). Declared in common/core/offset.hpp
// and common/render/whitted.hpp.
#include "core/exercise.hpp"
#include "core/offset.hpp"
#include "render/scene.hpp"
#include "render/whitted.hpp"
#include "shading/shading.hpp"

#include <bit>
#include <cmath>

namespace rt {

// @book offset
Vec3 offset_origin(const Vec3& p, const Vec3& n) {
    // @exercise 6.1 | offset_origin | book §6.3
    // Work on the bits: adding k to a positive float's bit pattern moves it k units in the
    // last place, whatever its size. Moving away from zero means adding to |p|, so the
    // step takes p's sign as well as n's.
    using C = OffsetConstants<Real>;
    using Int = std::conditional_t<sizeof(Real) == 4, std::int32_t, std::int64_t>;
    Vec3 result;
    for (int k = 0; k < 3; ++k) {
        const Int step = Int(Real(C::ulps) * n[k]);
        const Int bits = std::bit_cast<Int>(p[k]) + (p[k] < 0 ? -step : step);
        const Real far = std::bit_cast<Real>(bits);
        result[k] = std::abs(p[k]) < C::origin ? p[k] + C::fixed_step * n[k] : far;
    }
    return result;
    // @end
}
// @book-end

// @book direct
Color direct_light(const Scene& scene, const Light& light, int light_index, const ShadePoint& sp,
                   TraceContext& context) {
    // @exercise 6.2 | direct_light | book §6.2
    const LightSample l = light.sample(sp.p);
    // Nothing to add, so no ray to cast: a black light, or one behind the surface.
    if (l.color == Color(0) || glm::dot(sp.side, l.direction) <= 0) return Color(0);
    // Up to the light and not including it: a point light sits at t = distance.
    const Real end = std::isfinite(l.distance) ? std::nextafter(l.distance, Real(0)) : kInfinity;
    const SpawnedRay shadow = spawn_ray(sp, l.direction, end, scene.offset);
    if (in_shadow(scene, shadow, light_index, l.color, context)) return Color(0);
    Color c = lambert(sp.diffuse, l.color, sp.n, l.direction);
    if (sp.material.has_specular()) {
        ++context.counters.specular_terms;
        c += blinn_phong_highlight(sp.material.specular, sp.material.exponent, l.color, sp.n, l.direction, sp.v);
    }
    return c;
    // @end
}
// @book-end

}  // namespace rt
