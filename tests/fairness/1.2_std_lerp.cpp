// fairness 1.2 pass: std::lerp (C++20) from l to r at x / nx
// The library's own interpolation, which rounds in its own way.
// @helpers
#include <cmath>
// @body
    return Vec2(std::lerp(win.l, win.r, x / Real(nx)), std::lerp(win.b, win.t, y / Real(ny)));
