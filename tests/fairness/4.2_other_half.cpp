// fairness 4.2 fail: the half-open rule the other way up, an end "above" when p.y >= its y
// Still counts a vertex once, but a point on a bottom edge is now out and one on a top edge
// in: the contract says nudge up, which keeps the bottom edge.
// @body
    bool inside = false;
    const std::size_t m = polygon.size();
    for (std::size_t i = 0, j = m - 1; i < m; j = i++) {
        const bool rising = polygon[i].y < polygon[j].y;
        const Vec2 &a = rising ? polygon[i] : polygon[j], &b = rising ? polygon[j] : polygon[i];
        if ((a.y >= p.y) != (b.y >= p.y)) {
            const Real x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
            if (x > p.x) inside = !inside;
        }
    }
    return inside;
