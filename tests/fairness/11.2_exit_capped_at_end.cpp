// fairness 11.2 fail: each cell's search also capped at t_end, where the ray leaves the grid's box
// t_end is the clipped interval's end: in the last cell it takes away the pad that the
// cell's exit adds, and a wall lying in the grid's face is lost as without the pad. The
// interval's own end needs no cap here: best.t starts there.
// @body
    GridWalk w;
    if (!start(ray, interval, w)) return false;
    do {
        const Real exit = std::min(cell_exit(ray, w), w.t_end);
        if (hit_cell(surfaces, w, ray, Interval{interval.min, std::min(best.t, exit)}, best)) return true;
    } while (next(ray, w));
    return false;
