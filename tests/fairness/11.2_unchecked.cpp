// fairness 11.2 fail: no cell check: the first hit found in any cell ends the walk
// The trap of course Figure 9.23: a primitive listed in this cell may be hit beyond it,
// behind a closer hit in a cell the walk has not reached yet.
// @body
    GridWalk w;
    if (!start(ray, interval, w)) return false;
    do {
        if (hit_cell(surfaces, w, ray, Interval{interval.min, best.t}, best)) return true;
    } while (next(ray, w));
    return false;
