// {"type": "point", "position": [x, y, z], "color": [r, g, b]}
#include "io/scene_types.hpp"

namespace rt {

namespace {

Light read_point_light(const Fields& f) {
    Light l;
    l.type = Light::Type::point;
    l.position = f.vec3("position");
    return l;
}

}  // namespace

RTLAB_LIGHT_TYPE(point, read_point_light);

}  // namespace rt
