// fairness 14.1 fail: (sx + u) / n without keeping it below 1: for u just below 1 in the last
// stratum, n - 1 + u rounds up to n and the point is exactly 1, outside [0, 1)^2 (a sample on
// the next pixel's edge, a shutter time at the close)
// @body
    const int sx = k % n, sy = k / n;
    return Vec2((Real(sx) + u.x) / Real(n), (Real(sy) + u.y) / Real(n));
