#pragma once
// Walls in the faces of a structure's box (tests of chapters 11 and 12): a closed cube mesh is
// its own box, so each of its faces lies in a face of the grid or of the tree's root cell.
// A ray that starts a hair from such a wall and meets it a little further on, at a grazing
// angle, has its hit computed a rounding error outside the part of the ray inside the box
// about half the time: past the far face seen from inside, before the near face seen from
// outside. A structure that clips its search to the box without a pad loses those hits.
#include "support/accel_check.hpp"

#include <cmath>

namespace rt::test {

struct Walls {
    Vec3 centre{Real(0.37), Real(-0.21), Real(0.13)};
    Real size = Real(2.3);
    SurfaceList list;

    Walls() { list.add(Mesh(subdivided_cube(centre, size, 4))); }

    // 1,200 rays, 200 at each face: from inside the cube, or from outside.
    RaySet rays(bool outside) const {
        const Box b = list.bounding_box();
        Rng rng;
        RaySet set;
        for (int k = 0; k < 1200; ++k) {
            const int axis = k % 3;
            const bool high = (k / 3) % 2;
            const Real face = high ? b.max[axis] : b.min[axis], inward = high ? -1 : 1;
            Vec3 from = centre + rng.vec(-0.45, 0.45) * size, along = rng.vec(-1, 1);
            along[axis] = 0;
            Vec3 at = from + along * (std::pow(Real(10), rng(-3, -1.5)) * size);  // on the wall
            at[axis] = face;
            from[axis] = face + (outside ? -inward : inward) * std::pow(Real(10), rng(-6, -4)) * size;
            set.add(Ray{from, at - from});
        }
        return set;
    }
};

}  // namespace rt::test
