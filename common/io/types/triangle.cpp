// {"type": "triangle", "vertices": [a, b, c]}, counter-clockwise seen from the front.
#include "io/scene_types.hpp"

namespace rt {

namespace {

Shape read_triangle(const Fields& f) {
    const auto v = f.points("vertices", limits::triangle_vertices);
    return Triangle(v[0], v[1], v[2]);
}

}  // namespace

RTLAB_SURFACE_TYPE(triangle, read_triangle);

}  // namespace rt
