// fairness 11.2 fail: every cell searched from where the ray enters the grid (the clipped start)
// A wall lying in the grid's near face is hit a rounding error before that point about
// half the time; searched from there, the first cell refuses the hit and the walk goes on
// to whatever lies behind the wall.
// @body
    Interval inside = interval;
    if (!clip(ray, inside)) return false;
    GridWalk w;
    if (!start(ray, interval, w)) return false;
    do {
        if (hit_cell(surfaces, w, ray, Interval{inside.min, std::min(best.t, cell_exit(ray, w))}, best)) return true;
    } while (next(ray, w));
    return false;
