// fairness 4.1 fail: a normal mostly along y keeps x and y
// The cases for z and x are right; a floor (normal along y) is projected onto a line.
// @body
    const Real x = std::abs(n.x), y = std::abs(n.y), z = std::abs(n.z);
    if (z > x && z > y) return {0, 1};
    if (y > x) return {0, 1};
    return {1, 2};
