// The shading layer at the edges of its ranges: light stays finite however close or far.
#include "shading/light.hpp"
#include "support.hpp"

#include <cmath>

using namespace rt;

TEST_SUITE("common") {
TEST_CASE("a light at the shading point, or far away and tiny, gives finite light") {
    Light point;
    point.position = Vec3(1, 2, 3);
    const LightSample at = point.sample(Vec3(1, 2, 3));
    CHECK(at.color == Color(0));
    CHECK(std::isfinite(at.direction.x + at.direction.y + at.direction.z));
    Light sun;
    sun.type = Light::Type::directional;
    sun.direction = Vec3(0, Real(-1e-30), 0);  // its square underflows in float (and 1e-200 in double)
    CHECK(sun.sample(Vec3(0)).direction == Vec3(0, 1, 0));
}
}  // TEST_SUITE("common")
