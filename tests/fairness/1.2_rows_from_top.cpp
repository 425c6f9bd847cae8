// fairness 1.2 fail: rows counted from the top, v = t - (t - b) y / ny
// The image-file convention; the contract's j counts up from the bottom row, like v.
// @body
    const Real u = win.l + (win.r - win.l) * x / Real(nx);
    const Real v = win.t - (win.t - win.b) * y / Real(ny);
    return Vec2(u, v);
