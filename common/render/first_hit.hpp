#pragma once
// The integrators whose colour starts at the ray's first hit: every shading model but the
// pictures of rays and of search cost. Self says what a ray brings back from its hit (or
// from nothing: a null record), in
//   Color shade(const Scene&, const Ray&, const HitRecord* rec, TraceContext&) const;
// and the search is made here, once for all of them: one ray at a time in Li, and for a
// tile of centre samples (Integrator::trace_centre_tile) eight camera rays at a time, 2 x 4
// pixels whose rays leave the eye together, as one packet (Scene::hit_packet, book §10.5).
// A packet finds each ray the hit that ray finds alone, so the pixels are the same, bit for
// bit; the search tests far fewer boxes for them.
#include "render/integrator.hpp"
#include "render/scene.hpp"

#include <algorithm>
#include <span>

namespace rt {

// A packet's pixels: two rows of four (the squarer the packet, the fewer boxes it enters
// that some of its rays miss; book §10.5).
inline constexpr int kPacketRows = 2, kPacketColumns = kPacketRays / kPacketRows;

template <class Self>
class FirstHitIntegrator : public Integrator {
public:
    Color Li(const Scene& scene, const Ray& ray, TraceContext& context) const final {
        HitRecord rec;
        const bool found = scene.hit(ray, context.interval, rec);
        return self().shade(scene, ray, found ? &rec : nullptr, context);
    }

    void trace_centre_tile(const Scene& scene, const View& view, Tile tile, Sampler& sampler, RayCounters& counters,
                           Image& image) const final {
        for (int y0 = tile.y0; y0 < tile.y1; y0 += kPacketRows)
            for (int x0 = tile.x0; x0 < tile.x1; x0 += kPacketColumns) {
                Ray rays[kPacketRays];
                int at[kPacketRays][2];  // each ray's pixel (i, y)
                int n = 0;
                for (int y = y0; y < std::min(y0 + kPacketRows, tile.y1); ++y)
                    for (int i = x0; i < std::min(x0 + kPacketColumns, tile.x1); ++i) {
                        rays[n] = view.pixel_ray(i, image.height - 1 - y);  // image rows go down, v goes up
                        at[n][0] = i;
                        at[n][1] = y;
                        ++n;
                    }
                HitRecord recs[kPacketRays];
                // A camera ray's interval is its context's (TraceContext::interval): all of t >= 0.
                const unsigned found = scene.hit_packet(std::span(rays, std::size_t(n)), Interval{}, recs);
                for (int k = 0; k < n; ++k)
                    centre_sample(
                        [&](const Ray& ray, TraceContext& context) {
                            return self().shade(scene, ray, found >> k & 1 ? &recs[k] : nullptr, context);
                        },
                        rays[k], at[k][0], at[k][1], sampler, counters, image);
            }
    }

private:
    const Self& self() const { return static_cast<const Self&>(*this); }
};

}  // namespace rt
