#pragma once
// The limits on resources: inputs past these are refused before any work is spent on them.
// With the scene's value limits (geometry/limits.hpp) they are the one table the loaders,
// the command line, the JSON Schema test, book appendix A and the README all read.
#include <string>

namespace rt::limits {

struct Range {
    const char* name;    // as the messages say it
    double min, max;     // both allowed
    const char* what;    // "" for a count or a plain number; else its unit ("bytes", "degrees")
    const char* schema;  // where the JSON Schema states it (JSON pointer); "" if not a scene value
};

// @book resources
inline constexpr Range json_depth{"JSON nesting depth", 1, 32, "", ""};
inline constexpr Range scene_file_bytes{"scene file size", 0, 16 << 20, "bytes", ""};
inline constexpr Range obj_file_bytes{"OBJ file size", 0, 1 << 30, "bytes", ""};
inline constexpr Range image_file_bytes{"image file size", 0, 1 << 29, "bytes", ""};
inline constexpr Range image_side{"image width and height", 1, 16384, "pixels", ""};
inline constexpr Range image_pixels{"image size", 1, 1 << 25, "pixels", ""};
inline constexpr Range samples_per_pixel{"samples per pixel", 1, 65536, "",
                                         "/properties/antialiasing/properties/samples"};
inline constexpr Range image_samples{"samples per image", 1, 4294967296.0, "width x height x spp", ""};
inline constexpr Range threads{"threads", 0, 1024, "", ""};
// The search structures list a primitive in every cell or leaf it reaches; these bound the
// lists' memory (4 bytes an entry), before they are allocated: 10^4 balls in one place
// would list each in all 2 x 10^4 cells of a grid, 800 MB.
inline constexpr Range grid_entries{"grid entries", 0, 1 << 26, "(primitives listed, summed over the cells)", ""};
inline constexpr Range bsp_entries{"BSP entries", 0, 1 << 28, "(primitives listed, summed over the leaves)", ""};
// @book-end

// True if `value` is in the range (a NaN never is).
inline constexpr bool contains(const Range& r, double value) {
    return value >= r.min && value <= r.max;
}

// "must be in 0..7", "must be in 1e-06..1e+08": the tail of a message.
std::string describe(const Range& r);
// "icosphere subdivisions must be in 0..7, not 9"
std::string refuse(const Range& r, double value);

}  // namespace rt::limits
