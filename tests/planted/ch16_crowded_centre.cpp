// A planted bug (book §16.2): the polar map with radius u_x instead of sqrt(u_x), a disk whose
// points crowd its centre (a quarter of them within radius 1/4, not a sixteenth). Every lens
// point is inside the disk and the bokeh keeps its round outline, but each disc of light is
// brighter in the middle than at its rim: chapter 16's statistical test must catch it on the
// scene of small far lights (lights), however few pixels the discs cover.
#include "render/camera.hpp"

#include <cmath>
#include <numbers>

#define lens_point lens_point_as_written
#include "../../solutions/ch16_depth_of_field.cpp"
#undef lens_point

namespace rt {
Vec2 lens_point(const Vec2& u, LensShape shape) {
    if (shape == LensShape::square) return lens_point_as_written(u, shape);
    const Real phi = 2 * std::numbers::pi_v<Real> * u.y;
    return Vec2(u.x * std::cos(phi), u.x * std::sin(phi));
}
}  // namespace rt
