// {"type": "directional", "direction": [x, y, z], "color": [r, g, b]}: the direction the
// light travels, any non-zero length.
#include "io/scene_types.hpp"

namespace rt {

Light read_directional_light(const Fields& f) {
    Light l;
    l.type = Light::Type::directional;
    l.direction = f.direction("direction");
    return l;
}

}  // namespace rt
