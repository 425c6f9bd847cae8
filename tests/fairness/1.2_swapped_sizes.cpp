// fairness 1.2 fail: the pixel width computed from ny and the height from nx
// Right for every square image, stretched for any other.
// @body
    const Real u = win.l + (win.r - win.l) * x / Real(ny);
    const Real v = win.b + (win.t - win.b) * y / Real(nx);
    return Vec2(u, v);
