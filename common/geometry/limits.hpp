#pragma once
// Every limit a scene or a mesh may ask for, stated once (resources: core/limits.hpp). The
// generators, the loaders and the command line check them and name them in their messages,
// the JSON Schema is tested against them (tests/schema_test.py), book appendix A prints
// this table and the README lists the resource limits.
//
// Why the value limits: a number the loader accepts must stay finite through everything the
// renderer does with it, in float as in double. Coordinates within ±1e8 keep every product
// the ray tests form (at most the cube of a coordinate difference, 8e24) far below float's
// 3.4e38; reflectances at most 1 keep a ray tree from amplifying light; radiances at most
// 1e6 keep a pixel's sum over lights finite.
#include "core/limits.hpp"

namespace rt::limits {

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
// A ray through a CSG object computes the spans of every shape under it, through shared
// shapes too: 1024 instances of a 1024-ball shape would be 10^6 sphere tests a ray.
inline constexpr Range csg_leaves{"CSG leaves", 2, 16384, "(shapes under one CSG object, counted through instances)",
                                  ""};
// Meshes.
inline constexpr Range obj_face_corners{"OBJ face corners", 3, 255, "", ""};  // tinyobjloader keeps a byte
inline constexpr Range mesh_vertices{"mesh vertices", 3, 1 << 25, "", ""};
inline constexpr Range mesh_triangles{"mesh triangles", 1, 1 << 25, "", ""};
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
                                csg_leaves,
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
                                threads,
                                grid_entries,
                                bsp_entries};

}  // namespace rt::limits
