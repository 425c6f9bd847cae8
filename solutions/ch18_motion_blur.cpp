// Chapter 18 exercises: motion blur (book §18, course §9.11.5). Declared in
// common/render/camera.hpp and common/geometry/sphere.hpp.
#include "core/exercise.hpp"
#include "geometry/sphere.hpp"
#include "render/camera.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

// @book shutter
Real shutter_time(int k, int n, Real u, Real open, Real close) {
    // @exercise 18.1 | shutter_time | book §18.2
    const Real s = (Real(k) + u) / Real(n);  // in stratum k of [0, 1)
    // open + s (close - open) may round up to close for s just below 1: keep it inside.
    return std::min(open + s * (close - open), std::max(open, std::nextafter(close, open)));
    // @end
}
// @book-end

// @book swept-box
Box swept_box(const Sphere& sphere) {
    // @exercise 18.2 | swept_box | book §18.1
    // The centre moves along a straight line, so the sphere stays inside the box of its
    // two ends: the box of the sphere at time 0 grown by the box at time 1.
    const Vec3 r(sphere.radius);
    Box box{sphere.center - r, sphere.center + r};
    const Vec3 end = sphere.center + sphere.motion;
    box.expand(Box{end - r, end + r});
    return box;
    // @end
}
// @book-end

}  // namespace rt
