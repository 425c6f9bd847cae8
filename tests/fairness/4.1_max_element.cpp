// fairness 4.1 pass: the dropped axis as the index of the largest |n_i|, the others in order
// @helpers
#include <algorithm>
// @body
    const std::array<Real, 3> size{std::abs(n.x), std::abs(n.y), std::abs(n.z)};
    const int drop = int(std::max_element(size.begin(), size.end()) - size.begin());
    std::array<int, 2> keep{};
    for (int axis = 0, k = 0; axis < 3; ++axis)
        if (axis != drop) keep[k++] = axis;
    return keep;
