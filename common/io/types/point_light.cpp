// {"type": "point", "position": [x, y, z], "color": [r, g, b]}
#include "io/scene_types.hpp"

namespace rt {

Light read_point_light(const Fields& f) {
    Light l;
    l.type = Light::Type::point;
    l.position = f.vec3("position");
    return l;
}

}  // namespace rt
