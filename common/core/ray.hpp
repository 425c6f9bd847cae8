#pragma once
#include "core/real.hpp"

namespace rt {

// @book ray
// p(t) = e + t d. The direction is deliberately *not* normalised: instancing transforms
// rays into object space, where the length of d changes, and every hit routine must still
// return the t of the original ray.
struct Ray {
    Vec3 origin;     // e
    Vec3 direction;  // d, any non-zero length
    Real time = 0;   // when the ray is cast, on the clock things move by (motion blur): in [open, close) of the shutter

    Vec3 at(Real t) const { return origin + t * direction; }
};
// @book-end

}  // namespace rt
