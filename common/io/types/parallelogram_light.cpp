// {"type": "parallelogram", "corner": [x, y, z], "edge_a": [x, y, z], "edge_b": [x, y, z],
// "color": [r, g, b]}: an area light (chapter 15), the points corner + u edge_a + v edge_b
// for u, v in [0, 1]. The edges must span a parallelogram: not zero, not parallel.
#include "io/scene_types.hpp"

namespace rt {

namespace {

Light read_parallelogram_light(const Fields& f) {
    Light l;
    l.type = Light::Type::parallelogram;
    l.position = f.vec3("corner");
    l.edge_a = f.direction("edge_a");
    l.edge_b = f.direction("edge_b");
    const Vec3 a = unit_vector(l.edge_a), b = unit_vector(l.edge_b);
    if (!(glm::length(glm::cross(a, b)) > Real(1e-6))) f.fail("edge_b", "is parallel to edge_a: the light has no area");
    for (const Vec3& corner : {l.position + l.edge_a, l.position + l.edge_b, l.position + l.edge_a + l.edge_b})
        for (int k = 0; k < 3; ++k)
            if (!limits::contains(limits::coordinate, double(corner[k])))
                f.fail("", "the light reaches past the coordinate limits (" +
                               limits::refuse(limits::coordinate, double(corner[k])) + ")");
    return l;
}

}  // namespace

RTLAB_LIGHT_TYPE(parallelogram, read_parallelogram_light);

}  // namespace rt
