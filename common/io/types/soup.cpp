// {"type": "soup", "center": [x, y, z], "size": s, "scale": e, "count": n, "seed": k}
#include "geometry/procedural.hpp"
#include "io/scene_types.hpp"

namespace rt {

namespace {

Shape read_soup(const Fields& f) {
    return Mesh(triangle_soup(f.vec3("center"), f.length("size"), f.length("scale"),
                              f.integer("count", limits::soup_count),
                              std::uint64_t(f.integer("seed", limits::soup_seed, 1))));
}

}  // namespace

RTLAB_SURFACE_TYPE(soup, read_soup);

}  // namespace rt
