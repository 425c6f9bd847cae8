// {"type": "sphere", "center": [x, y, z], "radius": R}
#include "io/scene_types.hpp"

namespace rt {

Shape read_sphere(const Fields& f) {
    return Sphere(f.vec3("center"), f.length("radius"));
}

}  // namespace rt
