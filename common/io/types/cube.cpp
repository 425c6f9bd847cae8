// {"type": "cube", "center": [x, y, z], "size": s, "subdivisions": n}
#include "geometry/procedural.hpp"
#include "io/scene_types.hpp"

namespace rt {

namespace {

Shape read_cube(const Fields& f) {
    return Mesh(
        subdivided_cube(f.vec3("center"), f.length("size"), f.integer("subdivisions", limits::cube_subdivisions, 1)));
}

}  // namespace

RTLAB_SURFACE_TYPE(cube, read_cube);

}  // namespace rt
