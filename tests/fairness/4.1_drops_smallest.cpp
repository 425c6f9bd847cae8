// fairness 4.1 fail: the axis of the smallest component dropped
// The projection then has the smallest area: a polygon facing along z is flattened to a line.
// @body
    const Real x = std::abs(n.x), y = std::abs(n.y), z = std::abs(n.z);
    if (z < x && z < y) return {0, 1};
    if (y < x) return {0, 2};
    return {1, 2};
