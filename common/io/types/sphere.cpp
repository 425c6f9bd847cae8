// {"type": "sphere", "center": [x, y, z], "radius": R, "moves_to": [x, y, z]}: with
// "moves_to", the sphere moves (chapter 18): its centre is `center` at time 0 and `moves_to`
// at time 1 of the shutter's scale.
#include "io/scene_types.hpp"

namespace rt {

namespace {

Shape read_sphere(const Fields& f) {
    const Vec3 c = f.vec3("center");
    return Sphere(c, f.length("radius"), f.has("moves_to") ? f.vec3("moves_to") - c : Vec3(0));
}

}  // namespace

RTLAB_SURFACE_TYPE(sphere, read_sphere);

}  // namespace rt
