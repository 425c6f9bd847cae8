// fairness 4.2 pass: the crossing as fma(p.y - a.y, dx/dy, a.x) from the lower end, counted in an int
// The inverse slope first and one fused multiply-add: other bits than the reference's, the
// same in both polygons that share the edge.
// @helpers
#include <cmath>
// @body
    int crossings = 0;
    const std::size_t m = polygon.size();
    for (std::size_t k = 0; k < m; ++k) {
        Vec2 a = polygon[k], b = polygon[(k + 1) % m];
        if (b.y < a.y) std::swap(a, b);
        if (a.y <= p.y && p.y < b.y && std::fma(p.y - a.y, (b.x - a.x) / (b.y - a.y), a.x) > p.x) ++crossings;
    }
    return crossings % 2 == 1;
