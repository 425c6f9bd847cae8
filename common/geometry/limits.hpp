#pragma once
// Every limit a scene, a mesh, an image or a command line may ask for, stated once. The
// generators, the loaders and the command line check them and name them in their messages,
// the JSON Schema is tested against them (tests/schema_test.py), book appendix A prints
// this table and the README lists the resource limits.
//
// Why the value limits: a number the loader accepts must stay finite through everything the
// renderer does with it, in float as in double. Coordinates within ±1e8 keep every product
// the ray tests form (at most the cube of a coordinate difference, 8e24) far below float's
// 3.4e38; reflectances at most 1 keep a ray tree from amplifying light; radiances at most
// 1e6 keep a pixel's sum over lights finite.
#include <string>

namespace rt::limits {

struct Range {
    const char* name;    // as the messages say it
    double min, max;     // both allowed
    const char* what;    // "" for a count or a plain number; else its unit ("bytes", "degrees")
    const char* schema;  // where the JSON Schema states it (JSON pointer); "" if not a scene value
};

// @book limits
// Values in a scene file.
inline constexpr Range coordinate{"coordinate", -1e8, 1e8, "", "/$defs/coordinate"};
inline constexpr Range length{"length", 1e-6, 1e8, "", "/$defs/length"};
inline constexpr Range reflectance{"reflectance", 0, 1, "", "/$defs/reflectance/items"};
inline constexpr Range radiance{"radiance", 0, 1e6, "", "/$defs/radiance/items"};
inline constexpr Range exponent{"Phong exponent", 1e-3, 1e6, "", "/$defs/material/properties/exponent"};
inline constexpr Range index_of_refraction{"index of refraction", 0.01, 100, "", "/$defs/material/properties/ior"};
inline constexpr Range recursion_depth{"recursion depth", 0, 64, "", "/properties/max_depth"};
inline constexpr Range angle{"angle", -3600, 3600, "degrees", "/$defs/transform_step/properties/degrees"};
inline constexpr Range field_of_view{"field of view", 1e-3, 179.9, "degrees", "/$defs/camera/properties/fov"};
inline constexpr Range aperture{"aperture", 0, 1e8, "", "/$defs/camera/properties/aperture"};
inline constexpr Range shutter{"shutter time", 0, 1, "", "/$defs/camera/properties/shutter/items"};
inline constexpr Range glossy_width{"glossy width", 0, 16, "", "/$defs/material/properties/glossy"};
// Counts in a scene file.
inline constexpr Range triangle_vertices{"triangle vertices", 3, 3, "", "/$defs/surface/oneOf/1/properties/vertices"};
inline constexpr Range polygon_vertices{"polygon vertices", 3, 100000, "",
                                        "/$defs/surface/oneOf/2/properties/vertices"};
inline constexpr Range icosphere_subdivisions{"icosphere subdivisions", 0, 7, "",
                                              "/$defs/surface/oneOf/4/properties/subdivisions"};
inline constexpr Range cube_subdivisions{"cube subdivisions", 1, 256, "",
                                         "/$defs/surface/oneOf/5/properties/subdivisions"};
inline constexpr Range terrain_cells{"terrain cells", 1, 2048, "", "/$defs/surface/oneOf/6/properties/cells"};
inline constexpr Range soup_count{"soup triangles", 1, 1000000, "", "/$defs/surface/oneOf/7/properties/count"};
inline constexpr Range soup_seed{"soup seed", 0, 2147483647, "", "/$defs/surface/oneOf/7/properties/seed"};
inline constexpr Range csg_operands{"CSG operands", 2, 1024, "", "/$defs/surface/oneOf/10/properties/operands"};
inline constexpr Range csg_thin{"CSG thin", 0, 1e8, "", "/$defs/surface/oneOf/10/properties/thin"};
// Resources: inputs past these are refused before any work is spent on them.
inline constexpr Range json_depth{"JSON nesting depth", 1, 32, "", ""};
inline constexpr Range scene_file_bytes{"scene file size", 0, 16 << 20, "bytes", ""};
inline constexpr Range obj_file_bytes{"OBJ file size", 0, 1 << 30, "bytes", ""};
inline constexpr Range obj_face_corners{"OBJ face corners", 3, 255, "", ""};  // tinyobjloader keeps a byte
inline constexpr Range mesh_vertices{"mesh vertices", 3, 1 << 25, "", ""};
inline constexpr Range mesh_triangles{"mesh triangles", 1, 1 << 25, "", ""};
inline constexpr Range image_file_bytes{"image file size", 0, 1 << 29, "bytes", ""};
inline constexpr Range image_side{"image width and height", 1, 16384, "pixels", ""};
inline constexpr Range image_pixels{"image size", 1, 1 << 25, "pixels", ""};
inline constexpr Range samples_per_pixel{"samples per pixel", 1, 65536, "",
                                         "/properties/antialiasing/properties/samples"};
inline constexpr Range image_samples{"samples per image", 1, 4294967296.0, "width x height x spp", ""};
inline constexpr Range threads{"threads", 0, 1024, "", ""};
// @book-end

inline constexpr Range all[] = {coordinate,
                                length,
                                reflectance,
                                radiance,
                                exponent,
                                index_of_refraction,
                                recursion_depth,
                                angle,
                                field_of_view,
                                aperture,
                                shutter,
                                glossy_width,
                                triangle_vertices,
                                polygon_vertices,
                                icosphere_subdivisions,
                                cube_subdivisions,
                                terrain_cells,
                                soup_count,
                                soup_seed,
                                csg_operands,
                                csg_thin,
                                json_depth,
                                scene_file_bytes,
                                obj_file_bytes,
                                obj_face_corners,
                                mesh_vertices,
                                mesh_triangles,
                                image_file_bytes,
                                image_side,
                                image_pixels,
                                samples_per_pixel,
                                image_samples,
                                threads};

// True if `value` is in the range (a NaN never is).
inline constexpr bool contains(const Range& r, double value) {
    return value >= r.min && value <= r.max;
}

// "must be in 0..7", "must be in 1e-06..1e+08": the tail of a message.
std::string describe(const Range& r);
// "icosphere subdivisions must be in 0..7, not 9"
std::string refuse(const Range& r, double value);

}  // namespace rt::limits
