#pragma once
// The explorer's frames: what a progressive pass leaves for the page, and the ways it can
// travel (book §0, "The lab explorer": ./lab bench explore measures them).
#include "core/names.hpp"
#include "render/image.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace rt {

struct ExploreFrame {
    std::uint64_t id = 0;          // counts every frame the session made
    std::uint64_t generation = 0;  // counts the changes of scene, camera or settings
    int width = 0, height = 0;     // of this frame: smaller than the view while it moves
    int samples = 0;               // samples per pixel so far
    int target_samples = 0;        // where refining stops
    double render_ms = 0;          // of the pass that made it
    double finish_ms = 0;          // after it: into the running sum and 8-bit sRGB
    double pass_ms = 0;            // since the pass before it was handed on: the frame interval
    double mrays_per_s = 0;        // rays of that pass (every kind) over its time
    // What the search cost that pass, per ray (book §10.6): boxes (nodes) visited and
    // primitives tested.
    double nodes_per_ray = 0, primitives_per_ray = 0;
    std::vector<std::uint8_t> rgb;  // sRGB, 8 bits, 3 per pixel, top row first
};

// Linear colours to 8-bit sRGB, clamped to [0, 1].
void to_rgb(const Image& image, std::vector<std::uint8_t>& rgb);
// Adds a pass to the running sum (double, 3 per pixel) and writes the mean of the `samples`
// passes summed so far: one sweep over the memory, not one to add and one to convert.
void accumulate_to_rgb(const Image& pass, std::vector<double>& sum, int samples, std::vector<std::uint8_t>& rgb);

// rgb: the bytes as they are; rgba: alpha 255 added; png; jpeg: quality 90.
enum class FrameFormat : std::uint8_t { rgb, rgba, png, jpeg };
inline constexpr auto kFrameFormatNames = names_of<FrameFormat>({"rgb", "rgba", "png", "jpeg"});
const char* mime_type(FrameFormat format);
std::string encode_frame(const ExploreFrame& frame, FrameFormat format);

}  // namespace rt
