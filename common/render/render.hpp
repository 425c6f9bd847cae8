#pragma once
#include "render/antialiasing.hpp"
#include "render/image.hpp"
#include "render/scene.hpp"
#include "render/strata.hpp"

#include <atomic>
#include <cstdint>
#include <optional>

namespace rt {

struct RenderOptions {
    int width = 400;
    int height = 300;
    int spp = 1;                // samples per pixel; 1 = the pixel centre, as in course §9.2
    Antialiasing antialiasing;  // where the samples go, and the filter (book §14)
    std::uint64_t seed = 0;     // selects every pixel's random stream
    int threads = 0;            // 0 = all cores
    bool progress = false;      // progress bar on stderr
    // A progressive pass (the explorer, common/app/explore*): only the samples [first_sample,
    // first_sample + sample_count) of a pixel's spp (the pattern's strata, in order), averaged;
    // 0 = all of them. Their random numbers start each pixel's streams afresh: a pass gives
    // the same image as a whole render only from sample 0 (the explorer seeds each pass apart).
    int first_sample = 0;
    int sample_count = 0;
    // When set (by another thread), the tiles not yet started are skipped: the explorer's
    // pass, overtaken by a camera move, ends early and its image is thrown away.
    const std::atomic<bool>* cancel = nullptr;
};

struct RenderResult {
    Image image;
    RayCounters counters;
    double seconds = 0;
    int threads = 0;  // worker threads actually used
};

// Throws std::invalid_argument unless the image size, samples and threads are within
// limits.hpp (a render that would take unbounded memory or time is refused before it
// starts), and the pattern can place that many samples.
void check_budget(const RenderOptions& options);

// The one render loop: square tiles spread over the cores by TBB, each pixel with its own
// sampler. Exceptions from the integrator (an unfinished exercise) reach the caller.
RenderResult render(const Scene& scene, const RenderOptions& options);

// The rest of a camera sample (book §16, §18): a place on the lens when the camera has one,
// and a time in the shutter interval when something in the scene moves; each drawn in its
// own dimension, stratified and shuffled against the pixel's samples. Nothing is drawn for
// what the scene does not need.
void lens_and_time(const View& view, bool moving, Sampler& sampler, CameraSample& sample);

// How the samples of a pixel divide every dimension: as the pixel pattern does (the Sampler
// takes no strata when the count is not a square).
Strata strata_of(const Antialiasing& aa);

// What the ray through the centre of image pixel (x, y) (y down from the top, as image
// viewers count) sees: the picking use of ray tracing from the course's FAQ. The
// integrator runs on that ray once more, recording every ray it casts: the ray tree
// (empty for integrators that record nothing, those of chapters 01-05).
struct Pick {
    Ray ray;
    std::optional<HitRecord> hit;
    RayTree tree;
    Color color{0};  // what the integrator returned for the ray
};
Pick pick(const Scene& scene, const RenderOptions& options, int x, int y);
// Throws std::invalid_argument unless (x, y) is a pixel of the image.
void check_pick(const RenderOptions& options, int x, int y);

}  // namespace rt
