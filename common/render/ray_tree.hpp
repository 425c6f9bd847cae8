#pragma once
// The tree of rays behind one pixel (book §7.5): every ray an integrator cast for it, what
// the ray hit and what it brought back, and the weight its colour was multiplied by on the
// way to the pixel. --pick prints it as JSON and --svg draws it. Recorded only when a
// context carries a tree, so the render loop pays one test of a null pointer per ray.
#include "core/counters.hpp"
#include "core/interval.hpp"
#include "core/ray.hpp"
#include "geometry/hit_record.hpp"

#include <vector>

namespace rt {

struct RayNode {
    RayKind kind = RayKind::camera;
    int parent = -1;  // index in RayTree::nodes; -1 for the camera ray
    int depth = 0;
    Ray ray;
    Interval interval;
    bool hit = false;  // for a shadow ray: blocked
    HitRecord record;  // the closest hit, when hit (for a shadow ray: the blocker)
    int light = -1;    // shadow rays: which of the scene's lights
    // What the ray's colour was multiplied by before it was added to its parent's, and why
    // ("light colour", "mirror colour", "Schlick R", "1 - R", ...). A ray that came back
    // through a dielectric also carries Beer's attenuation, folded in here.
    Color weight{1};
    const char* weight_of = "";
    Color radiance{0};      // what came back along the ray (for a shadow ray: 1 if it reaches the light, 0 if not;
                            // the light's colour is its weight)
    const char* note = "";  // why the tree stops here, when it does ("total internal reflection", ...)
};

struct RayTree {
    std::vector<RayNode> nodes;
};

}  // namespace rt
