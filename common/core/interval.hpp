#pragma once
#include "core/real.hpp"

namespace rt {

// The range of ray parameters a query accepts: [min, max], both ends included, the
// course's [t0, t1]. A closest-hit search shrinks max as it finds hits.
struct Interval {
    Real min = 0;
    Real max = kInfinity;

    // False for NaN: a NaN t is never a hit.
    bool contains(Real t) const { return min <= t && t <= max; }
};

}  // namespace rt
