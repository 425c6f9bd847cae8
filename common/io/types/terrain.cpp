// {"type": "terrain", "center": [x, y, z], "size": s, "height": h, "cells": n}
#include "geometry/procedural.hpp"
#include "io/scene_types.hpp"

namespace rt {

namespace {

Shape read_terrain(const Fields& f) {
    return Mesh(terrain(f.vec3("center"), f.length("size"), f.number("height", limits::coordinate),
                        f.integer("cells", limits::terrain_cells, 64)));
}

}  // namespace

RTLAB_SURFACE_TYPE(terrain, read_terrain);

}  // namespace rt
