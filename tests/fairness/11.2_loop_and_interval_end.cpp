// fairness 11.2 pass: the walk as a while loop, each cell capped at the interval's end
// The cells are searched from the ray's own start up to each one's padded exit, as §11.3
// says. Capping at interval.max instead of best.t is the same search: hit_cell() caps at
// best.t itself.
// @body
    GridWalk w;
    if (!start(ray, interval, w)) return false;
    bool more = true;
    while (more) {
        const Interval part{interval.min, std::min(interval.max, cell_exit(ray, w))};
        if (hit_cell(surfaces, w, ray, part, best)) return true;
        more = next(ray, w);
    }
    return false;
