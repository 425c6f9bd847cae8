// fairness 11.1 pass: a zero component tested with == 0, the index clamped as an int
// d == 0 is true for +0 and -0 alike, so the parallel axes get no step and no plane; the
// index is converted first and clamped with std::min and std::max.
// @body
    if (!clip(ray, interval)) return false;
    const Vec3 p = ray.at(interval.min);
    for (int a = 0; a < 3; ++a) {
        const int i = int(std::floor((p[a] - bounds_.min[a]) / cell_size_[a]));
        walk.cell[a] = std::max(0, std::min(n_[a] - 1, i));
        const Real d = ray.direction[a];
        if (d == 0) {
            walk.step[a] = 0;
            walk.t_max[a] = kInfinity;
            continue;
        }
        walk.step[a] = d > 0 ? 1 : -1;
        const int plane = d > 0 ? walk.cell[a] + 1 : walk.cell[a];
        walk.t_max[a] = (boundary(a, plane) - ray.origin[a]) / d;
    }
    walk.t_end = interval.max;
    return true;
