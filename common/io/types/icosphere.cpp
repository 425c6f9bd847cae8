// {"type": "icosphere", "center": [x, y, z], "radius": R, "subdivisions": n}
#include "geometry/procedural.hpp"
#include "io/scene_types.hpp"

namespace rt {

namespace {

Shape read_icosphere(const Fields& f) {
    return Mesh(
        icosphere(f.vec3("center"), f.length("radius"), f.integer("subdivisions", limits::icosphere_subdivisions, 2)));
}

}  // namespace

RTLAB_SURFACE_TYPE(icosphere, read_icosphere);

}  // namespace rt
