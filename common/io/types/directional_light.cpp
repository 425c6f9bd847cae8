// {"type": "directional", "direction": [x, y, z], "color": [r, g, b]}: the direction the
// light travels, any non-zero length.
#include "io/scene_types.hpp"

namespace rt {

namespace {

Light read_directional_light(const Fields& f) {
    Light l;
    l.type = Light::Type::directional;
    l.direction = f.direction("direction");
    return l;
}

}  // namespace

RTLAB_LIGHT_TYPE(directional, read_directional_light);

}  // namespace rt
