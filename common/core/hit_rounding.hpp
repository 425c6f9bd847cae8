#pragma once
// The slack every search structure gives the boxes it culls by, so that it finds the hits
// brute force finds wherever a scene sits (far from the origin, in float, too).
#include "core/box.hpp"

#include <algorithm>
#include <limits>

namespace rt {

// How far outside the box of what it tests a primitive's test can put a hit. A polygon's
// test, for one, rounds the point where the ray meets its plane to a unit in the last
// place of the coordinates and then asks if it is inside: a ray that passes a rounding
// error outside an edge in the box's face is a hit the box test misses. Far from the
// origin in float a unit is no longer small (1/4 at 3e6, 8 at 1e8), and a structure that
// culls by the exact box loses hits brute force finds (at 3e6, a floor's edge hit 0.115
// outside). 16 units of the largest coordinate, as the grid has: the far-from-origin test
// needs 1; in double near the origin it is nothing (4e-14 at 10).
inline Real hit_rounding(const Box& box) {
    if (box.empty()) return 0;
    const Vec3 reach = glm::max(glm::abs(box.min), glm::abs(box.max));
    return Real(16) * std::numeric_limits<Real>::epsilon() * std::max({reach.x, reach.y, reach.z});
}

// The box a structure searches for what it holds: grown by the rounding of the hits inside.
// One rule for the BVHs' nodes and the grid's clip and pad (the BSP's pad is larger: it
// covers its planes too). A child's grown box stays inside its parent's: the parent holds
// it, and its coordinates are no smaller.
inline Box grown_by_rounding(const Box& box) {
    const Vec3 r(hit_rounding(box));
    return box.empty() ? box : Box{box.min - r, box.max + r};
}

}  // namespace rt
