// {"type": "polygon", "vertices": [...]}: planar, simple, convex or concave.
#include "io/scene_types.hpp"

namespace rt {

Shape read_polygon(const Fields& f) {
    return Polygon(f.points("vertices", limits::polygon_vertices));
}

}  // namespace rt
