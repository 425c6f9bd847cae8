#pragma once
#include "core/real.hpp"

namespace rt {

// An axis-aligned bounding box: the `box` of the course's bounding-box() function.
struct Box {
    Vec3 min{kInfinity};
    Vec3 max{-kInfinity};

    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    void expand(const Vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void expand(const Box& b) {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
};

}  // namespace rt
