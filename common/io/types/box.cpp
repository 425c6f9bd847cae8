// {"type": "box", "min": [x, y, z], "max": [x, y, z]}: an axis-aligned solid box (chapter 13)
#include "io/scene_types.hpp"

namespace rt {

namespace {

Shape read_box(const Fields& f) {
    return Cuboid(f.vec3("min"), f.vec3("max"));
}

}  // namespace

RTLAB_SURFACE_TYPE(box, read_box);

}  // namespace rt
