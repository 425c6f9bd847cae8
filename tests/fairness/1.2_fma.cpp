// fairness 1.2 pass: u = fma(x, (r - l)/nx, l): the pixel's width first, one rounding for the rest
// (book §1.3) The same map; for the centre pixel of a 3 x 3 image on [-1, 1] it gives -5.55e-17
// for 0, a rounding the contract allows.
// @helpers
#include <cmath>
// @body
    const Real u = std::fma(x, (win.r - win.l) / Real(nx), win.l);
    const Real v = std::fma(y, (win.t - win.b) / Real(ny), win.b);
    return Vec2(u, v);
