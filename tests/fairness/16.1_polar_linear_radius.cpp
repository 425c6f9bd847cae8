// fairness 16.1 fail: the polar map with radius u.x instead of sqrt(u.x): half the samples fall
// within radius 1/2, a quarter of the disk's area, so the lens is not uniform (the blur is
// brighter in its middle); its strata are also stretched into long arcs (§16.2)
// @body
    const Vec2 square = Real(2) * u - Vec2(1);
    if (shape == LensShape::square) return square;
    const Real r = u.x, phi = 2 * std::numbers::pi_v<Real> * u.y;
    return Vec2(r * std::cos(phi), r * std::sin(phi));
