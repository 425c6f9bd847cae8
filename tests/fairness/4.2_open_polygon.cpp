// fairness 4.2 fail: the closing edge, from the last vertex back to the first, never tested
// The polygon is walked as an open path: every point whose rightward ray
// crosses the closing edge comes out on the wrong side.
// @body
    bool inside = false;
    for (std::size_t i = 1; i < polygon.size(); ++i) {
        const bool rising = polygon[i].y < polygon[i - 1].y;
        const Vec2 &a = rising ? polygon[i] : polygon[i - 1], &b = rising ? polygon[i - 1] : polygon[i];
        if ((a.y > p.y) != (b.y > p.y)) {
            const Real x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
            if (x > p.x) inside = !inside;
        }
    }
    return inside;
