// fairness 11.1 fail: the next plane is the cell's upper side whichever way the ray moves
// Moving towards -x the ray leaves a cell through its lower side, plane i, not i + 1.
// @body
    if (!clip(ray, interval)) return false;
    const Vec3 p = ray.at(interval.min);
    for (int a = 0; a < 3; ++a) {
        const Real cell = std::floor((p[a] - bounds_.min[a]) / cell_size_[a]);
        walk.cell[a] = int(std::clamp(cell, Real(0), Real(n_[a] - 1)));
        const Real d = ray.direction[a];
        walk.step[a] = d > 0 ? 1 : (d < 0 ? -1 : 0);
        walk.t_max[a] = walk.step[a] == 0 ? kInfinity : (boundary(a, walk.cell[a] + 1) - ray.origin[a]) / d;
    }
    walk.t_end = interval.max;
    return true;
