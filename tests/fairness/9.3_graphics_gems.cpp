// fairness 9.3 pass: Arvo's min/max accumulation (Graphics Gems I): per entry of M, the smaller of
// m_ij min_j and m_ij max_j goes to the new min, the larger to the new max
// @helpers
#include <algorithm>
// @body
    Box result;
    result.min = result.max = to_world.t;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const Real a = to_world.m[j][i] * box.min[j], b = to_world.m[j][i] * box.max[j];
            result.min[i] += std::min(a, b);
            result.max[i] += std::max(a, b);
        }
    return result;
