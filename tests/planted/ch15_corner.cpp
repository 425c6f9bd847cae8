// A planted bug (book §15.1): every light sample at the light's corner, a point light with
// hard shadows in the wrong place. Chapter 15's statistical test must catch it.
#include "core/sampler.hpp"
#include "shading/light.hpp"

#define light_point light_point_as_written
#include "../../solutions/ch15_soft_shadows.cpp"
#undef light_point

namespace rt {
Vec3 light_point(const Light& light, const Vec2&) {
    return light.position;
}
}  // namespace rt
