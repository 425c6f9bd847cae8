// A planted bug (book §16.2): lens points in [0, 2]^2 instead of [-1, 1]^2, a lens not
// centred on the eye. Chapter 16's statistical test must catch it.
#include "render/camera.hpp"

#define lens_point lens_point_as_written
#include "../../solutions/ch16_depth_of_field.cpp"
#undef lens_point

namespace rt {
Vec2 lens_point(const Vec2& u, LensShape shape) {
    return lens_point_as_written(u, shape) + Vec2(1);
}
}  // namespace rt
