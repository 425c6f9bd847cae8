#pragma once
// An integrator turns a ray into a colour: each chapter's shading model is one, and the
// render loop does not know which.
#include "core/counters.hpp"
#include "core/ray.hpp"
#include "core/sampler.hpp"
#include "render/camera.hpp"
#include "render/image.hpp"
#include "render/ray_tree.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

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

// The pixels [x0, x1) x [y0, y1) of a tile, in image rows (row 0 at the top).
struct Tile {
    int x0, y0, x1, y1;
};

// A tile of a pass that takes each pixel's one sample at its centre, through the pinhole, at
// the shutter's opening (render/render.cpp decides when): what the render loop makes for
// such a sample in general, without the sample's draws, the per-sample loop or the sum (the
// average of one float sample is that sample).
//
// centre_sample is one pixel of it: the sampler moved to the pixel, the camera ray counted,
// and the colour `li` brings back for it (its Li, given the ray and its context) kept in the
// image, if it is finite.
template <class LiFn>
void centre_sample(LiFn&& li, const Ray& ray, int i, int y, Sampler& sampler, RayCounters& counters, Image& image) {
    sampler.start_pixel(std::uint64_t(y) * std::uint64_t(image.width) + std::uint64_t(i));
    sampler.start_sample(0);
    counters.count(RayKind::camera);
    TraceContext context{sampler, counters};
    context.time = ray.time;
    const Color L = li(ray, context);
    if (std::isfinite(L.r + L.g + L.b))
        image.at(i, y) = L + 0.0f;  // -0 + 0 is +0, as in the render loop's sum
    else
        ++counters.nonfinite_samples;  // the pixel stays 0, the empty sum's average
}

// The tile pixel by pixel. `li` is the integrator's Li.
template <class LiFn>
void trace_centre_tile(LiFn&& li, const View& view, Tile tile, Sampler& sampler, RayCounters& counters, Image& image) {
    for (int y = tile.y0; y < tile.y1; ++y) {
        const int j = image.height - 1 - y;  // image rows go down, v goes up
        for (int i = tile.x0; i < tile.x1; ++i) centre_sample(li, view.pixel_ray(i, j), i, y, sampler, counters, image);
    }
}

class Integrator {
public:
    virtual ~Integrator() = default;
    virtual Color Li(const Scene& scene, const Ray& ray, TraceContext& context) const = 0;

    // A tile of centre samples (trace_centre_tile), in one call: an IntegratorOf<Self> makes
    // it with Self's Li called directly, inlined into the loop, instead of a virtual call per
    // pixel (~4 ns of a bunny camera ray's ~75 shaded by normals: the call, its saved
    // registers and its record kept in memory).
    virtual void trace_centre_tile(const Scene& scene, const View& view, Tile tile, Sampler& sampler,
                                   RayCounters& counters, Image& image) const {
        rt::trace_centre_tile([&](const Ray& ray, TraceContext& c) { return Li(scene, ray, c); }, view, tile, sampler,
                              counters, image);
    }
};

// The base of the library's integrators: Self's Li, called without the virtual call in the
// render loop's tiles of centre samples.
template <class Self>
class IntegratorOf : public Integrator {
public:
    void trace_centre_tile(const Scene& scene, const View& view, Tile tile, Sampler& sampler, RayCounters& counters,
                           Image& image) const final {
        const Self& self = static_cast<const Self&>(*this);
        rt::trace_centre_tile([&](const Ray& ray, TraceContext& c) { return self.Self::Li(scene, ray, c); }, view, tile,
                              sampler, counters, image);
    }
};

}  // namespace rt
