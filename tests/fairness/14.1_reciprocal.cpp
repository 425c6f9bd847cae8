// fairness 14.1 pass: multiplication by the reciprocal, x * (1 / n), instead of division: a
// point at a stratum's low edge can land one ulp below it, in the stratum before; the contract
// allows a few ulps either way, and the pattern is as stratified as the reference's
// @body
    const int sx = k % n, sy = k / n;
    const Real inverse = Real(1.0) / Real(n);
    const Real below_one = std::nextafter(Real(1), Real(0));
    return Vec2(std::min((Real(sx) + u.x) * inverse, below_one), std::min((Real(sy) + u.y) * inverse, below_one));
