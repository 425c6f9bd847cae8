// fairness 4.2 pass: each edge's crossing computed from its left end (the lower one on a tie)
// Any rule that names one end of an edge whatever the walking direction gives both polygons
// that share it the same bits (book §4.3); this one compares x first.
// @body
    bool inside = false;
    const std::size_t m = polygon.size();
    for (std::size_t i = 0, j = m - 1; i < m; j = i++) {
        Vec2 a = polygon[i], b = polygon[j];
        if (b.x < a.x || (b.x == a.x && b.y < a.y)) std::swap(a, b);
        if ((a.y > p.y) != (b.y > p.y)) {
            const Real x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
            if (x > p.x) inside = !inside;
        }
    }
    return inside;
