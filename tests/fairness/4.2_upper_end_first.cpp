// fairness 4.2 pass: each edge ordered with its upper end first, and the crossing taken from
// there: any order that does not depend on the walking direction gives a shared edge's
// crossing the same bits in both polygons (book §4.3)
// @body
    bool inside = false;
    const std::size_t m = polygon.size();
    for (std::size_t i = 0, j = m - 1; i < m; j = i++) {
        Vec2 top = polygon[i], bottom = polygon[j];
        if (top.y < bottom.y) std::swap(top, bottom);
        if ((top.y > p.y) != (bottom.y > p.y)) {
            const Real x = top.x + (p.y - top.y) * (bottom.x - top.x) / (bottom.y - top.y);
            if (x > p.x) inside = !inside;
        }
    }
    return inside;
