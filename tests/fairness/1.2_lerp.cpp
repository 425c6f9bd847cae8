// fairness 1.2 pass: the window's edges blended, (1 - s) l + s r with s = x / nx
// The windowing transform as an interpolation between the edges: exact at both of them.
// @body
    const Real s = x / Real(nx), q = y / Real(ny);
    return Vec2((1 - s) * win.l + s * win.r, (1 - q) * win.b + q * win.t);
