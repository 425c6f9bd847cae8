#pragma once
// Every size limit a scene may ask for, stated once. The generators and the polygon check
// them, the scene loader names them in its messages, the JSON Schema is tested against
// them (tests/schema_test.py) and book appendix A prints this table.
namespace rt::limits {

struct Range {
    const char* name;    // as the loader's messages say it
    long long min, max;  // both allowed
    const char* schema;  // where the JSON Schema states it (JSON pointer)
};

// @book limits
inline constexpr Range triangle_vertices{"triangle vertices", 3, 3, "/$defs/surface/oneOf/1/properties/vertices"};
inline constexpr Range polygon_vertices{"polygon vertices", 3, 100000, "/$defs/surface/oneOf/2/properties/vertices"};
inline constexpr Range icosphere_subdivisions{"icosphere subdivisions", 0, 7,
                                              "/$defs/surface/oneOf/4/properties/subdivisions"};
inline constexpr Range cube_subdivisions{"cube subdivisions", 1, 256, "/$defs/surface/oneOf/5/properties/subdivisions"};
inline constexpr Range terrain_cells{"terrain cells", 1, 2048, "/$defs/surface/oneOf/6/properties/cells"};
inline constexpr Range soup_count{"soup triangles", 1, 1000000, "/$defs/surface/oneOf/7/properties/count"};
inline constexpr Range soup_seed{"soup seed", 0, 2147483647, "/$defs/surface/oneOf/7/properties/seed"};
// @book-end

inline constexpr Range all[] = {triangle_vertices, polygon_vertices, icosphere_subdivisions,
                                cube_subdivisions, terrain_cells,    soup_count,
                                soup_seed};

}  // namespace rt::limits
