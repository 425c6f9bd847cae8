#pragma once
// The kinds of thing a scene file can hold, each read by its own module in io/types/. A
// later chapter adds a kind with one file there and one line in scene_types.cpp; the loader
// itself does not change.
#include "geometry/shape.hpp"
#include "io/json_reader.hpp"
#include "shading/light.hpp"
#include "shading/material.hpp"

#include <vector>

namespace rt {

// One "type" of /surfaces: its name, the keys it takes (besides "type", "name" and
// "material"), and how to read it.
struct SurfaceType {
    const char* name;
    std::vector<const char*> keys;
    Shape (*read)(const Fields& fields);
};

struct LightType {
    const char* name;
    std::vector<const char*> keys;  // besides "type" and "color"
    Light (*read)(const Fields& fields);
};

const std::vector<SurfaceType>& surface_types();
const std::vector<LightType>& light_types();

// "a, b or c": the names of a table, for messages.
template <class T>
std::string type_names(const std::vector<T>& types) {
    std::string list;
    for (std::size_t i = 0; i < types.size(); ++i)
        list += std::string(i == 0 ? "" : i + 1 == types.size() ? " or " : ", ") + types[i].name;
    return list;
}

// The modules (io/types/*.cpp).
Shape read_sphere(const Fields& f);
Shape read_triangle(const Fields& f);
Shape read_polygon(const Fields& f);
Shape read_mesh_file(const Fields& f);
Shape read_icosphere(const Fields& f);
Shape read_cube(const Fields& f);
Shape read_terrain(const Fields& f);
Shape read_soup(const Fields& f);
Shape read_box(const Fields& f);
Light read_point_light(const Fields& f);
Light read_directional_light(const Fields& f);
Light read_parallelogram_light(const Fields& f);
// Materials have one kind so far; its keys are checked here too.
Material read_material(const Fields& f);
// A list of transform steps at `key` (io/types/transform.cpp); fails for a singular result.
Affine read_transform(const Fields& f, const char* key);

}  // namespace rt
