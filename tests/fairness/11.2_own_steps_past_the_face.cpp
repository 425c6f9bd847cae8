// fairness 11.2 fail: the walk steps by itself, stopping only at t_end, and indexes one cell past the far face
// t_end is where the ray leaves the grid's box, padded a little: the plane of the far face
// comes before it, so the walk takes one step more, into a cell outside the grid.
// expect: crashed
// @body
    GridWalk w;
    if (!start(ray, interval, w)) return false;
    for (;;) {
        if (hit_cell(surfaces, w, ray, Interval{interval.min, std::min(best.t, cell_exit(ray, w))}, best)) return true;
        int a = 0;
        for (int k = 1; k < 3; ++k)
            if (w.t_max[k] < w.t_max[a]) a = k;
        if (w.t_max[a] > w.t_end) return false;
        w.cell[a] += w.step[a];
        w.t_max[a] = (boundary(a, w.cell[a] + (w.step[a] > 0)) - ray.origin[a]) / ray.direction[a];
    }
