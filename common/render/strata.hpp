#pragma once
// Where a pixel's samples go in each of their dimensions (book §14.2, §15.2): the pixel
// itself, the light, the lens, the shutter, the glossy lobe. Every dimension is stratified
// the one way the Sampler was told (the pattern of RenderOptions: random, regular or
// jittered); the pixel's strata are taken in order, and every other dimension's are
// shuffled against them, the course's remedy for samples that would otherwise move in step.
#include "core/sampler.hpp"
#include "render/antialiasing.hpp"
#include "render/camera.hpp"

namespace rt {

// A point of the unit square [0, 1)^2 for the current sample, in dimension d: the sample's
// stratum of the side x side grid (exercise 14.1 places it there). Only the sample's first
// point in a dimension is stratified; any later one (a second glossy bounce, a second area
// light) is uniform and independent, since one tied to the first would bias a path that
// depends on both.
Vec2 sample_square(Sampler& sampler, Dimension d);

// The current sample's stratum of `count` on a line in dimension d, and where in it: the
// place u in [0, 1) (0.5 for regular strata); stratum 0 of 1 for random samples.
struct LineSample {
    int stratum, count;
    Real u;
};
LineSample sample_line(Sampler& sampler, Dimension d);

// The film position of the current sample of pixel (i, j) (j up from the bottom): the pixel
// dimension's point of the unit square (sample_square, so the pattern is the Sampler's, as
// for every other dimension) through the filter, as pbrt's GetCameraSample puts a sampler
// and a filter together. A pixel of one random sample with the box filter takes its centre,
// as in course §9.2, and draws nothing. Lens and time stay at the pinhole and time 0 until a
// camera asks for them (lens_and_time in render.hpp).
CameraSample camera_sample(int i, int j, PixelFilter filter, Sampler& sampler);

// Does every sample of such a pixel sit at its centre, drawing nothing? One sample,
// unstratified, through the box filter (camera_sample's first case; the render loop asks it
// too, to skip the sampling altogether).
inline bool at_centre(int count, Strata strata, PixelFilter filter) {
    return count == 1 && strata == Strata::none && filter == PixelFilter::box;
}

}  // namespace rt
