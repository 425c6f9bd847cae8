// fairness 16.1 pass: Shirley and Chiu's concentric map mirrored in the diagonal (u.x and u.y
// trade places for the disk): as uniform and as compact as the reference's orientation, and
// the lens is the same disk; only which stratum of u lands where differs
// @body
    const Vec2 square = Real(2) * u - Vec2(1);
    if (shape == LensShape::square) return square;
    const Real a = square.y, b = square.x;
    if (a == 0 && b == 0) return Vec2(0);
    const Real quarter = std::numbers::pi_v<Real> / 4;
    Real r, phi;
    if (std::abs(a) > std::abs(b)) {
        r = a;
        phi = quarter * (b / a);
    } else {
        r = b;
        phi = 2 * quarter - quarter * (a / b);
    }
    return Vec2(r * std::cos(phi), r * std::sin(phi));
