#pragma once
// The kinds of figure a description may name, each drawn by one function in its own file
// (NAME.cpp beside this one). Adding a kind: write that file, add its line here.
#include "geometry/sphere.hpp"
#include "io/json_reader.hpp"
#include "render/camera.hpp"
#include "svg.hpp"

#include <cstdint>
#include <vector>

// X(name in the description's "kind", function)
#define RTLAB_FIGURE_KINDS(X)                                 \
    X("camera-frame", camera_frame)                           \
    X("camera-rays", camera_rays)                             \
    X("ray-sphere", ray_sphere)                               \
    X("barycentric", barycentric)                             \
    X("crossing-rule", crossing_rule)                         \
    X("polygon-projection", polygon_projection)               \
    X("shading-vectors", shading_vectors)                     \
    X("shadow-offset", shadow_offset)                         \
    X("reflection", reflection)                               \
    X("refraction", refraction)                               \
    X("total-internal-reflection", total_internal_reflection) \
    X("instancing", instancing)                               \
    X("slab", slab)                                           \
    X("bvh-tree", bvh_tree)                                   \
    X("grid-walk", grid_walk)                                 \
    X("grid-trap", grid_trap)                                 \
    X("bsp-cases", bsp_cases)                                 \
    X("csg-spans", csg_spans)                                 \
    X("pixel-samples", pixel_samples)                         \
    X("stratum-pairing", stratum_pairing)                     \
    X("thin-lens", thin_lens)                                 \
    X("glossy-square", glossy_square)                         \
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
// The angle between two directions, in degrees, for a label.
double degrees_between(const rt::Vec3& a, const rt::Vec3& b);
// The description's "spheres", each {"center", "radius"}: the circles a flat figure's
// structures (a BVH, a grid, a BSP tree) are built over.
std::vector<rt::Sphere> spheres_of(const rt::Fields& in);
// One pixel's samples, as the render loop sets its Sampler up for them: the description's
// "samples" (a square number, at most `most`: the strata are side x side), "seed" and "pixel".
struct PixelSamples {
    int count, side;
    std::uint64_t seed, pixel;
};
PixelSamples pixel_samples_of(const rt::Fields& in, int most = 256);
// The description's one "ray", {"origin", "direction", "t_end"}: the ray, and how far along it
// the figure draws it.
struct DrawnRay {
    rt::Ray ray;
    rt::Real t_end;
};
DrawnRay ray_of(const rt::Fields& in);

// An orthographic view of a 3D figure, seen from the direction `toward_viewer` with `up`
// up the page: the page's axes are the frame the library's camera_basis (exercise 1.1)
// builds for an eye looking the other way.
struct View3 {
    rt::Basis uvw;
    View3(const rt::Vec3& toward_viewer, const rt::Vec3& up) : uvw(rt::camera_basis(-toward_viewer, up)) {}
    P2 operator()(const rt::Vec3& p) const { return {double(glm::dot(p, uvw.u)), double(glm::dot(p, uvw.v))}; }
};

}  // namespace figures
