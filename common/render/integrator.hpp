#pragma once
// An integrator turns a ray into a colour: each chapter's shading model is one, and the
// render loop does not know which.
#include "core/counters.hpp"
#include "core/ray.hpp"
#include "core/sampler.hpp"
#include "render/ray_tree.hpp"

#include <algorithm>

namespace rt {

struct Scene;

// What travels with every integrator call: the pixel's random numbers, the counters, and
// where in the ray tree this ray is. Recursive chapters (reflection, refraction) call Li
// again with child(...); nothing else needs a new parameter.
struct TraceContext {
    Sampler& sampler;
    RayCounters& counters;
    int depth = 0;                   // 0 for a camera ray, +1 per bounce
    RayKind kind = RayKind::camera;  // why this ray was cast
    Interval interval{};             // the t this ray accepts (secondary rays start past an offset)
    RayTree* tree = nullptr;         // --pick: record every ray here; null while rendering
    int parent = -1;                 // the node of the ray that cast this one
    int node = -1;                   // this ray's node, once open()ed
    Color weight{1};                 // for the tree: the factor this ray's colour will get
    const char* weight_of = "";
    float reach = 1;  // the product of the weights from the pixel down to this ray
    // When the camera ray was cast (chapter 18): every ray of its tree, shadow rays too,
    // sees the scene at that time.
    Real time = 0;

    // The context of a ray this one casts.
    TraceContext child(RayKind k, Interval iv, const Color& w, const char* why) const {
        const float share = std::max(w.r, std::max(w.g, w.b));
        return TraceContext{sampler, counters, depth + 1, k, iv, tree, node, -1, w, why, reach * share, time};
    }

    // Tree bookkeeping; each does nothing unless a tree is being recorded.
    void open(const Ray& ray) {
        if (!tree) return;
        RayNode n;
        n.kind = kind;
        n.parent = parent;
        n.depth = depth;
        n.ray = ray;
        n.interval = interval;
        n.weight = weight;
        n.weight_of = weight_of;
        node = int(tree->nodes.size());
        tree->nodes.push_back(n);
    }
    void record_hit(const HitRecord& rec) {
        if (!tree || node < 0) return;
        tree->nodes[std::size_t(node)].hit = true;
        tree->nodes[std::size_t(node)].record = rec;
    }
    void note(const char* why) {
        if (tree && node >= 0) tree->nodes[std::size_t(node)].note = why;
    }
    Color close(const Color& radiance) {
        if (tree && node >= 0) tree->nodes[std::size_t(node)].radiance = radiance;
        return radiance;
    }
};

class Integrator {
public:
    virtual ~Integrator() = default;
    virtual Color Li(const Scene& scene, const Ray& ray, TraceContext& context) const = 0;
};

}  // namespace rt
