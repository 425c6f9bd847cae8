// fairness 11.1 fail: the first plane of an axis the ray runs parallel to, found by dividing by +-0
// With the plane picked by the sign bit, (plane - origin) / +-0 comes out +infinity for an
// origin inside a cell, but 0 / -0 = NaN for an origin on a plane: the walk then stops there.
// @body
    if (!clip(ray, interval)) return false;
    const Vec3 p = ray.at(interval.min);
    for (int a = 0; a < 3; ++a) {
        const Real cell = std::floor((p[a] - bounds_.min[a]) / cell_size_[a]);
        walk.cell[a] = int(std::clamp(cell, Real(0), Real(n_[a] - 1)));
        const Real d = ray.direction[a];
        walk.step[a] = d > 0 ? 1 : (d < 0 ? -1 : 0);
        walk.t_max[a] = (boundary(a, walk.cell[a] + (std::signbit(d) ? 0 : 1)) - ray.origin[a]) / d;
    }
    walk.t_end = interval.max;
    return true;
