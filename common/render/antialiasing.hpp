#pragma once
// Antialiasing (book §14, course §9.11.1): where a pixel's samples go (the pattern) and how
// they are weighed into the pixel (the filter). stratified_point and tent_offset are the
// chapter 14 exercises (solutions/ch14_antialiasing.cpp); camera_sample in strata.hpp puts
// them together.
#include "core/names.hpp"
#include "core/real.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace rt {

// random: each sample anywhere in the pixel. regular: the centres of an n x n grid of
// strata. jittered: one sample anywhere in each stratum of the n x n grid.
enum class PixelPattern : std::uint8_t { random, regular, jittered };
// box: a sample counts for the pixel it falls in (the course's average). tent: the samples
// of a pixel spread over it and its neighbours with density 1 - |x| in each axis (x in
// pixels from its centre), so an edge is blended over two pixels instead of one.
enum class PixelFilter : std::uint8_t { box, tent };

struct Antialiasing {
    PixelPattern pattern = PixelPattern::random;
    PixelFilter filter = PixelFilter::box;
};

inline constexpr auto kPatternNames = names_of<PixelPattern>({"random", "regular", "jittered"});
inline constexpr auto kFilterNames = names_of<PixelFilter>({"box", "tent"});

// The side n of an n x n pattern of spp samples; nothing unless spp is a square.
std::optional<int> pattern_side(int spp);

// Exercise 14.1: sample k (0 <= k < n * n) of an n x n stratified pattern over the unit
// square: stratum (k mod n, k div n), at offset u in [0, 1)^2 inside it, that is
// ((k mod n + u.x) / n, (k div n + u.y) / n) to within a few units in the last place (so
// x * (1 / n) will do as well as x / n, though at a stratum's edge the two can fall on
// either side of it). Always inside [0, 1)^2: rounding must not push a point to 1.
Vec2 stratified_point(int k, int n, Vec2 u);

// Exercise 14.2: a uniform u in [0, 1) turned into an offset in [-1, 1) from the pixel centre
// (u = 0 gives -1, u = 1/2 the centre), distributed with the tent's density 1 - |x| (by
// inverting its distribution function). Monotone in u, so stratified u stay stratified.
Real tent_offset(Real u);

}  // namespace rt
