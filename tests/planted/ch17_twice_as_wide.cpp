// A planted bug (book §17.1): the glossy square twice as wide as the material says (a width
// taken for a half-width). Chapter 17's statistical test must catch it.
#include "shading/optics.hpp"

#define glossy_direction glossy_direction_as_written
#include "../../solutions/ch17_glossy_reflection.cpp"
#undef glossy_direction

namespace rt {
Vec3 glossy_direction(const Vec3& r, Real width, const Vec2& uv) {
    return glossy_direction_as_written(r, 2 * width, uv);
}
}  // namespace rt
