// fairness 11.2 fail: the walk goes on to the far face after a hit
// The right hit (best keeps the closest, each cell checked), but every cell the ray crosses
// is visited: the grid's whole point, stopping at the first cell with a hit, is lost.
// @body
    GridWalk w;
    if (!start(ray, interval, w)) return false;
    bool found = false;
    do {
        found |= hit_cell(surfaces, w, ray, Interval{interval.min, std::min(best.t, cell_exit(ray, w))}, best);
    } while (next(ray, w));
    return found;
