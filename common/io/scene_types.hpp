#pragma once
// The kinds of thing a scene file can hold, each read by its own module in io/types/. A new
// kind is one file there, which defines it with RTLAB_SURFACE_TYPE or RTLAB_LIGHT_TYPE, plus
// its entry in scene.schema.json; the loader itself does not change.
//
// The tables below are generated from the schema's lists of types (common/CMakeLists.txt),
// not gathered by static constructors: a module that only registered itself would sit in
// the static library unreferenced, and the linker would leave it out of every program. Here
// a type the schema lists without a module fails to link, and tests/schema_test.py fails on
// a module whose type the schema does not list.
#include "core/text.hpp"
#include "geometry/shape.hpp"
#include "io/json_reader.hpp"
#include "shading/light.hpp"
#include "shading/material.hpp"

#include <string>
#include <vector>

namespace rt {

// One "type" of /surfaces and how to read it. The reader asks for the keys the type takes;
// the loader reads "type", "name", "material", "transform" and "smooth" and then refuses
// the keys nobody asked about (Fields::done).
struct SurfaceType {
    const char* name;
    Shape (*read)(const Fields& fields);
};

// One "type" of /lights; the loader reads "type" and "color".
struct LightType {
    const char* name;
    Light (*read)(const Fields& fields);
};

// In a module of io/types/: RTLAB_SURFACE_TYPE(sphere, read_sphere) defines the type
// "sphere", read by read_sphere.
#define RTLAB_SURFACE_TYPE(type, reader)          \
    extern const SurfaceType surface_type_##type; \
    const SurfaceType surface_type_##type = {#type, reader}
#define RTLAB_LIGHT_TYPE(type, reader)        \
    extern const LightType light_type_##type; \
    const LightType light_type_##type = {#type, reader}

// Every type, in the schema's order (generated: build/.../io_types.cpp).
const std::vector<const SurfaceType*>& surface_types();
const std::vector<const LightType*>& light_types();

// "a, b or c": the names of a table, for messages.
template <class T>
std::string type_names(const std::vector<const T*>& types) {
    return or_list(types, [](const T* t) { return t->name; });
}

// Materials have one kind so far (io/types/phong_material.cpp).
Material read_material(const Fields& f);
// A list of transform steps at `key` (io/types/transform.cpp); fails for a singular result.
Affine read_transform(const Fields& f, const char* key);

}  // namespace rt
