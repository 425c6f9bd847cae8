// fairness 1.2 fail: divides by nx - 1, as if pixel centres sat on the window's edges
// The first and last pixel centres then land on l and r, and the window is stretched by one
// pixel.
// @body
    const Real u = win.l + (win.r - win.l) * (x - Real(0.5)) / Real(nx - 1);
    const Real v = win.b + (win.t - win.b) * (y - Real(0.5)) / Real(ny - 1);
    return Vec2(u, v);
