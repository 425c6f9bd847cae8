#pragma once
#include "common/real.hpp"

namespace rt {

// p(t) = e + t d. The direction is deliberately *not* normalised: instancing (a later
// chapter) transforms rays into object space, where the length of d changes, and every
// hit routine must still return the t of the original ray.
struct Ray {
    Vec3 origin;     // e
    Vec3 direction;  // d, any non-zero length

    Vec3 at(Real t) const { return origin + t * direction; }
};

}  // namespace rt
