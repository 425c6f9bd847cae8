#pragma once
// Samples in the dimensions after the pixel's (book §15.2): the light, the lens, the
// shutter, the glossy lobe. Each is stratified as the pixel's samples are (the pattern of
// RenderOptions: random, regular or jittered), and its strata are shuffled against the
// pixel's, the course's remedy for samples that would otherwise move in step.
#include "core/sampler.hpp"

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

}  // namespace rt
