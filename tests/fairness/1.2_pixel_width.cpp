// fairness 1.2 pass: the pixel's size first, then l + x * width
// @body
    const Real width = (win.r - win.l) / Real(nx), height = (win.t - win.b) / Real(ny);
    return Vec2(win.l + x * width, win.b + y * height);
