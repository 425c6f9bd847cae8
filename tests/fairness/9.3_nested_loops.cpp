// fairness 9.3 pass: the eight corners from three nested loops over each axis's two ends, min and max kept by hand
// @helpers
#include <algorithm>
// @body
    Vec3 low(kInfinity), high(-kInfinity);
    for (const Real x : {box.min.x, box.max.x})
        for (const Real y : {box.min.y, box.max.y})
            for (const Real z : {box.min.z, box.max.z}) {
                const Vec3 p = to_world.point(Vec3(x, y, z));
                low = glm::min(low, p);
                high = glm::max(high, p);
            }
    Box result;
    result.min = low;
    result.max = high;
    return result;
