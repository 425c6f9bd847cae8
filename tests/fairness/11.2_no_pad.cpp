// fairness 11.2 fail: each cell searched up to where the ray leaves it, without the pad
// The last cell's exit is the grid's face; a wall lying in that face is hit a rounding
// error past it about half the time, and no cell beyond it lists the wall (§11.3).
// @body
    GridWalk w;
    if (!start(ray, interval, w)) return false;
    do {
        const Real exit = std::min(w.t_max.x, std::min(w.t_max.y, w.t_max.z));
        if (hit_cell(surfaces, w, ray, Interval{interval.min, std::min(best.t, exit)}, best)) return true;
    } while (next(ray, w));
    return false;
