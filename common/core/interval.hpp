#pragma once
#include "core/real.hpp"

#include <cmath>

namespace rt {

// @book interval
// The range of ray parameters a query accepts: [min, max], both ends included, the
// course's [t0, t1]. A closest-hit search shrinks max as it finds hits.
struct Interval {
    Real min = 0;
    Real max = kInfinity;

    // False for NaN: a NaN t is never a hit.
    bool contains(Real t) const { return min <= t && t <= max; }
};
// @book-end

// The far end of a search past the best hit so far, widened by a few units in the last
// place. A primitive's own test decides "t <= max" after rounding, so a second primitive at
// exactly the best distance (a ray through an edge two triangles share) could be kept or
// lost depending on which one was tried first; tested against the widened end, both are
// found and `closer` (geometry/hit_record.hpp) picks one, whatever the search order.
inline Real widen_far(Real t) {
    return t + std::abs(t) * (4 * std::numeric_limits<Real>::epsilon());
}

}  // namespace rt
