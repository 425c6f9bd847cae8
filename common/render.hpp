#pragma once
#include "common/image.hpp"
#include "common/scene.hpp"

#include <cstdint>
#include <optional>

namespace rt {

struct RenderOptions {
    int width = 400;
    int height = 300;
    int spp = 1;             // samples per pixel; 1 = the pixel centre, as in §9.2
    std::uint64_t seed = 0;  // selects every pixel's random stream
    int threads = 0;         // 0 = all cores
    bool progress = false;   // progress bar on stderr
};

struct RenderResult {
    Image image;
    RayCounters counters;
    double seconds = 0;
    int threads = 0;  // worker threads actually used
};

// The one render loop: square tiles spread over the cores by TBB, each pixel with its own
// sampler. Exceptions from the integrator (an unfinished exercise) reach the caller.
RenderResult render(const Scene& scene, const RenderOptions& options);

// Where pixel (i, j) (j up from the bottom) puts a sample, in continuous image coordinates.
// One sample lands on the pixel centre; more are spread uniformly at random.
Vec2 pixel_sample(int i, int j, int spp, Sampler& sampler);

// What the ray through the centre of image pixel (x, y) (y down from the top, as image
// viewers count) sees: the picking use of ray tracing from the course's FAQ.
struct Pick {
    Ray ray;
    std::optional<HitRecord> hit;
};
Pick pick(const Scene& scene, const RenderOptions& options, int x, int y);

}  // namespace rt
