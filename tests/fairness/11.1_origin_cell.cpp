// fairness 11.1 fail: the first cell found from the ray's origin, not from where it enters
// Clipping decides only whether there is a walk; the cell is the one nearest the origin
// (clamped), which is right only when the ray enters straight across a face.
// @body
    Interval inside = interval;
    if (!clip(ray, inside)) return false;
    const Vec3 p = ray.at(interval.min);
    for (int a = 0; a < 3; ++a) {
        const Real cell = std::floor((p[a] - bounds_.min[a]) / cell_size_[a]);
        walk.cell[a] = int(std::clamp(cell, Real(0), Real(n_[a] - 1)));
        const Real d = ray.direction[a];
        walk.step[a] = d > 0 ? 1 : (d < 0 ? -1 : 0);
        walk.t_max[a] = walk.step[a] == 0
                            ? kInfinity
                            : (boundary(a, walk.cell[a] + (walk.step[a] > 0 ? 1 : 0)) - ray.origin[a]) / d;
    }
    walk.t_end = inside.max;
    return true;
