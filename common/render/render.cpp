#include "render/render.hpp"

#include "core/traversal_count.hpp"

#include "core/limits.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

namespace rt {

namespace {

constexpr int kTile = 16;

// A terminal progress bar, drawn by whichever worker finishes a tile once enough time has
// passed. Quiet for renders that finish within a second.
class Progress {
public:
    Progress(bool enabled, int total) : enabled_(enabled), total_(total), start_(Clock::now()) {}
    void tile_done() {
        const int done = ++done_;
        if (!enabled_) return;
        const double t = seconds();
        if (t < 1.0 && !shown_) return;
        std::unique_lock lock(mutex_, std::try_to_lock);
        if (!lock || (t - last_ < 0.1 && done < total_)) return;
        last_ = t;
        shown_ = true;
        const int width = 40, filled = width * done / total_;
        std::fprintf(stderr, "\r[%.*s%*s] %3d%% %6.1fs", filled, "########################################",
                     width - filled, "", 100 * done / total_, t);
        std::fflush(stderr);
    }
    void finish() {
        if (shown_) std::fputc('\n', stderr);
    }
    double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

private:
    using Clock = std::chrono::steady_clock;
    bool enabled_;
    int total_;
    Clock::time_point start_;
    std::atomic<int> done_{0};
    std::mutex mutex_;
    double last_ = -1;
    std::atomic<bool> shown_{false};
};

void check(const Scene& scene, const RenderOptions& o) {
    check_budget(o);
    if (!scene.integrator) throw std::invalid_argument("scene '" + scene.name + "' has no integrator");
}

}  // namespace

void check_budget(const RenderOptions& o) {
    const auto in = [](const limits::Range& r, double v, const char* what) {
        if (!limits::contains(r, v)) throw std::invalid_argument(std::string(what) + ": " + limits::refuse(r, v));
    };
    in(limits::image_side, o.width, "--width");
    in(limits::image_side, o.height, "--height");
    in(limits::samples_per_pixel, o.spp, "--spp");
    in(limits::threads, o.threads, "--threads");
    const double pixels = double(o.width) * double(o.height);
    in(limits::image_pixels, pixels, "--width x --height");
    in(limits::image_samples, pixels * double(o.spp), "--width x --height x --spp");
    if (o.antialiasing.pattern != PixelPattern::random && !pattern_side(o.spp))
        throw std::invalid_argument("--spp " + std::to_string(o.spp) + ": the " +
                                    kPatternNames[o.antialiasing.pattern] +
                                    " pattern takes n x n samples (1, 4, 9, 16, ...)");
}

namespace {

// Do the camera rays need a time? Only when something moves and the shutter is open for a while.
bool blurs_time(const View& view, bool moving) {
    return moving && view.shutter_open < view.shutter_close;
}

}  // namespace

void lens_and_time(const View& view, bool moving, Sampler& sampler, CameraSample& sample) {
    if (view.has_lens()) sample.lens = lens_point(sample_square(sampler, Dimension::lens), view.lens);
    if (blurs_time(view, moving)) {
        const LineSample t = sample_line(sampler, Dimension::time);
        sample.time = shutter_time(t.stratum, t.count, t.u, view.shutter_open, view.shutter_close);
    } else {
        sample.time = view.shutter_open;
    }
}

Strata strata_of(const Antialiasing& aa) {
    switch (aa.pattern) {
        case PixelPattern::regular:
            return Strata::centres;
        case PixelPattern::jittered:
            return Strata::jittered;
        case PixelPattern::random:
            break;
    }
    return Strata::none;
}

RenderResult render(const Scene& scene, const RenderOptions& o) {
    check(scene, o);
    const View view = scene.camera.view(o.width, o.height);
    const bool moving = scene.surfaces.moves();
    const Strata strata = strata_of(o.antialiasing);  // none when spp is not a square: set_strata
    const int side = pattern_side(o.spp).value_or(0);
    const int tiles_x = (o.width + kTile - 1) / kTile;
    const int tiles_y = (o.height + kTile - 1) / kTile;
    const int tiles = tiles_x * tiles_y;
    const int first = o.first_sample, count = o.sample_count > 0 ? o.sample_count : o.spp - first;
    if (first < 0 || count < 1 || first + count > o.spp)
        throw std::invalid_argument("samples " + std::to_string(first) + "+" + std::to_string(count) +
                                    " are not samples of a " + std::to_string(o.spp) + "-sample pixel");

    // One sample per pixel at its centre draws nothing and needs no sum (camera_sample,
    // lens_and_time): every render of one sample with the random pattern and the box filter,
    // through a pinhole, nothing blurred by motion (chapters 01-13 unless a scene asks for
    // more). Such tiles go to the integrator whole (Integrator::trace_centre_tile).
    const bool centre_only =
        at_centre(o.spp, strata, o.antialiasing.filter) && !view.has_lens() && !blurs_time(view, moving);
    const Integrator& integrator = *scene.integrator;
    RenderResult result;
    result.image = Image(o.width, o.height);
    Progress progress(o.progress, tiles);
    std::mutex counters_mutex;

    auto render_tile = [&](int tile) {
        if (o.cancel && o.cancel->load(std::memory_order_relaxed)) return;
        RayCounters counters;
        traversal_tally = {};  // a tile runs on one thread: what the searches count is this tile's
        const int x0 = (tile % tiles_x) * kTile, y0 = (tile / tiles_x) * kTile;
        const int x1 = std::min(x0 + kTile, o.width), y1 = std::min(y0 + kTile, o.height);
        Sampler sampler(o.seed, 0);  // one for the tile, moved from pixel to pixel
        sampler.set_strata(o.spp, side, strata);
        if (centre_only)
            integrator.trace_centre_tile(scene, view, Tile{x0, y0, x1, y1}, sampler, counters, result.image);
        else
            for (int y = y0; y < y1; ++y) {
                const int j = o.height - 1 - y;  // image rows go down, v goes up
                for (int i = x0; i < x1; ++i) {
                    sampler.start_pixel(std::uint64_t(y) * std::uint64_t(o.width) + std::uint64_t(i));
                    // Summed in double: a float sum of 65536 samples loses 7e-4 of each (the sum's
                    // step outgrows the samples); in double, n <= 2^16 floats add exactly, so the
                    // average of identical samples is that sample.
                    glm::dvec3 sum(0);
                    for (int k = first; k < first + count; ++k) {
                        sampler.start_sample(k);
                        CameraSample cs = camera_sample(i, j, o.antialiasing.filter, sampler);
                        lens_and_time(view, moving, sampler, cs);
                        const Ray ray = view.ray(cs);
                        counters.count(RayKind::camera);
                        TraceContext context{sampler, counters};
                        context.time = ray.time;
                        const Color L = integrator.Li(scene, ray, context);
                        // The image holds finite values whatever goes wrong upstream; --stats
                        // counts what was left out.
                        if (std::isfinite(L.r + L.g + L.b))
                            sum += glm::dvec3(L);
                        else
                            ++counters.nonfinite_samples;
                    }
                    result.image.at(i, y) = Color(sum / double(count));
                }
            }
        for (std::size_t d = 0; d < kDimensions; ++d) counters.draws[d] += sampler.draws()[d];
        counters.nodes_visited += traversal_tally.nodes;
        counters.primitives_tested += traversal_tally.items;
        {
            std::lock_guard lock(counters_mutex);
            result.counters += counters;
        }
        progress.tile_done();
    };

    const int threads = o.threads > 0 ? o.threads : tbb::this_task_arena::max_concurrency();
#if defined(RTLAB_TSAN)
    // Debian's libtbb is not built with ThreadSanitizer, so TBB's own synchronisation is
    // invisible to it and it reports TBB's internals. Under RTLAB_TSAN the same tiles run on
    // plain threads that take them from a counter: what is checked is our sharing.
    std::atomic<int> next{0};
    std::exception_ptr first_error;
    std::mutex error_mutex;
    std::vector<std::thread> workers;
    for (int w = 0; w < threads; ++w)
        workers.emplace_back([&] {
            try {
                for (int t; (t = next++) < tiles;) render_tile(t);
            } catch (...) {
                std::lock_guard lock(error_mutex);
                if (!first_error) first_error = std::current_exception();
                next = tiles;
            }
        });
    for (std::thread& w : workers) w.join();
    if (first_error) std::rethrow_exception(first_error);
#else
    tbb::task_arena arena(threads);
    arena.execute([&] {
        tbb::parallel_for(
            tbb::blocked_range<int>(0, tiles, 1),
            [&](const tbb::blocked_range<int>& r) {
                for (int t = r.begin(); t != r.end(); ++t) render_tile(t);
            },
            tbb::simple_partitioner());
    });
#endif
    progress.finish();
    result.seconds = progress.seconds();
    result.threads = threads;
    return result;
}

void check_pick(const RenderOptions& o, int x, int y) {
    if (x < 0 || x >= o.width || y < 0 || y >= o.height)
        throw std::invalid_argument("--pick: pixel " + std::to_string(x) + "," + std::to_string(y) +
                                    " is outside the " + std::to_string(o.width) + "x" + std::to_string(o.height) +
                                    " image");
}

Pick pick(const Scene& scene, const RenderOptions& o, int x, int y) {
    check(scene, o);
    check_pick(o, x, y);
    const View view = scene.camera.view(o.width, o.height);
    // The pixel's centre ray through the middle of the lens, at the shutter's opening.
    Pick result{view.pixel_ray(x, o.height - 1 - y), std::nullopt, {}, Color(0)};
    HitRecord rec;
    if (scene.hit(result.ray, Interval{}, rec)) result.hit = rec;
    Sampler sampler(o.seed, std::uint64_t(y) * std::uint64_t(o.width) + std::uint64_t(x));
    RayCounters counters;
    TraceContext context{sampler, counters};
    context.tree = &result.tree;
    context.time = result.ray.time;
    result.color = scene.integrator->Li(scene, result.ray, context);
    return result;
}

}  // namespace rt
