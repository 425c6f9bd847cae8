// fairness 11.1 fail: the first cell's index is not clamped
// A ray that enters through a far face (x = max) starts at index n, one past the last cell;
// the walk then reads the cell lists outside their array.
// expect: crashed
// @body
    if (!clip(ray, interval)) return false;
    const Vec3 p = ray.at(interval.min);
    for (int a = 0; a < 3; ++a) {
        walk.cell[a] = int(std::floor((p[a] - bounds_.min[a]) / cell_size_[a]));
        const Real d = ray.direction[a];
        walk.step[a] = d > 0 ? 1 : (d < 0 ? -1 : 0);
        walk.t_max[a] = walk.step[a] == 0
                            ? kInfinity
                            : (boundary(a, walk.cell[a] + (walk.step[a] > 0 ? 1 : 0)) - ray.origin[a]) / d;
    }
    walk.t_end = interval.max;
    return true;
