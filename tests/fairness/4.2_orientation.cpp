// fairness 4.2 pass: the crossing decided by the sign of a cross product, without computing x
// For an edge from its lower end a to its upper end b, the crossing lies right of p exactly
// when p is left of the edge: (b - a) x (p - a) > 0. Both polygons sharing the edge compute it
// from the same ordered pair, so they agree on every point.
// @body
    bool inside = false;
    const std::size_t m = polygon.size();
    for (std::size_t i = 0, j = m - 1; i < m; j = i++) {
        Vec2 a = polygon[i], b = polygon[j];
        if (b.y < a.y) std::swap(a, b);
        if ((a.y > p.y) != (b.y > p.y)) {
            const Real cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
            if (cross > 0) inside = !inside;
        }
    }
    return inside;
