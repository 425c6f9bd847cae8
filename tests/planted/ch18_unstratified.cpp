// A planted bug (book §18.2): a shutter time that ignores its stratum, anywhere in the
// interval. Unbiased, but as noisy as random sampling: chapter 18's statistical test must
// catch the extra variance.
#include "geometry/sphere.hpp"
#include "render/camera.hpp"

#define shutter_time shutter_time_as_written
#include "../../solutions/ch18_motion_blur.cpp"
#undef shutter_time

namespace rt {
Real shutter_time(int, int, Real u, Real open, Real close) {
    return shutter_time_as_written(0, 1, u, open, close);
}
}  // namespace rt
