// fairness 4.2 fail: a crossing at p itself counted (x >= p.x)
// A point on a right edge is then inside, and so is the same point in the neighbour to the
// right, which shares that edge as its left one.
// @body
    bool inside = false;
    const std::size_t m = polygon.size();
    for (std::size_t i = 0, j = m - 1; i < m; j = i++) {
        const bool rising = polygon[i].y < polygon[j].y;
        const Vec2 &a = rising ? polygon[i] : polygon[j], &b = rising ? polygon[j] : polygon[i];
        if ((a.y > p.y) != (b.y > p.y)) {
            const Real x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
            if (x >= p.x) inside = !inside;
        }
    }
    return inside;
