// fairness 1.2 fail: adds the half pixel again: x is already the pixel's centre, i + 0.5
// The course's formula is written for the index i; the contract's x already holds i + 0.5,
// so every ray goes half a pixel up and right.
// @body
    const Real u = win.l + (win.r - win.l) * (x + Real(0.5)) / Real(nx);
    const Real v = win.b + (win.t - win.b) * (y + Real(0.5)) / Real(ny);
    return Vec2(u, v);
