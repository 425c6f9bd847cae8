#pragma once
// The kinds of figure a description may name, each drawn by one function in its own file
// (NAME.cpp beside this one). Adding a kind: write that file, add its line here.
#include "io/json_reader.hpp"
#include "svg.hpp"

// X(name in the description's "kind", function)
#define RTLAB_FIGURE_KINDS(X)             \
    X("ray-sphere", ray_sphere)           \
    X("slab", slab)                       \
    X("bvh-tree", bvh_tree)               \
    X("grid-walk", grid_walk)             \
    X("grid-trap", grid_trap)             \
    X("bsp-cases", bsp_cases)             \
    X("csg-spans", csg_spans)             \
    X("pixel-samples", pixel_samples)     \
    X("stratum-pairing", stratum_pairing) \
    X("thin-lens", thin_lens)             \
    X("glossy-square", glossy_square)     \
    X("motion-blur", motion_blur)

namespace figures {

// A kind reads its inputs from the description (every key it asks about; the driver refuses
// the others) and draws with the library's own code. Bad inputs: in.fail(key, message).
#define RTLAB_FIGURE_DECLARE(name, function) Canvas function(const rt::Fields& in);
RTLAB_FIGURE_KINDS(RTLAB_FIGURE_DECLARE)
#undef RTLAB_FIGURE_DECLARE

// Helpers the kinds share.
// A label's text for a number: "0.707", "-2", at most `digits` significant digits.
std::string number(double v, int digits = 3);

}  // namespace figures
