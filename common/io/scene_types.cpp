#include "io/scene_types.hpp"

namespace rt {

const std::vector<SurfaceType>& surface_types() {
    static const std::vector<SurfaceType> types = {
        {"sphere", {"center", "radius", "moves_to"}, read_sphere},
        {"triangle", {"vertices"}, read_triangle},
        {"polygon", {"vertices"}, read_polygon},
        {"mesh", {"file", "scale", "translate"}, read_mesh_file},
        {"icosphere", {"center", "radius", "subdivisions"}, read_icosphere},
        {"cube", {"center", "size", "subdivisions"}, read_cube},
        {"terrain", {"center", "size", "height", "cells"}, read_terrain},
        {"soup", {"center", "size", "scale", "count", "seed"}, read_soup},
        {"box", {"min", "max"}, read_box},
    };
    return types;
}

const std::vector<LightType>& light_types() {
    static const std::vector<LightType> types = {
        {"point", {"position"}, read_point_light},
        {"directional", {"direction"}, read_directional_light},
        {"parallelogram", {"corner", "edge_a", "edge_b"}, read_parallelogram_light},
    };
    return types;
}

}  // namespace rt
