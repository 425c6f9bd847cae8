// fairness 4.2 fail: the crossing computed from the edge's end points in walking order
// Right for every point away from a shared edge, but a neighbour walks a shared edge the
// other way and rounds its crossing differently: points ulps from a slanted shared edge land in
// both polygons or in neither (book §4.3).
// @body
    bool inside = false;
    const std::size_t m = polygon.size();
    for (std::size_t i = 0, j = m - 1; i < m; j = i++) {
        const Vec2 &a = polygon[i], &b = polygon[j];
        if ((a.y > p.y) != (b.y > p.y)) {
            const Real x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
            if (x > p.x) inside = !inside;
        }
    }
    return inside;
