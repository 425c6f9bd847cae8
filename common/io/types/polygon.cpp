// {"type": "polygon", "vertices": [...]}: planar, simple, convex or concave.
#include "io/scene_types.hpp"

namespace rt {

namespace {

Shape read_polygon(const Fields& f) {
    return Polygon(f.points("vertices", limits::polygon_vertices));
}

}  // namespace

RTLAB_SURFACE_TYPE(polygon, read_polygon);

}  // namespace rt
