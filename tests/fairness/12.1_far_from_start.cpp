// fairness 12.1 fail: the far side searched from the part's start, not from the plane
// The right hit, but the far side's own planes are then judged from where the part starts,
// before the plane: cells the ray left before it reached this plane are opened again.
// @body
    const BspNode& n = node(ref);
    if (n.leaf()) return hit_leaf(surfaces, n, ray, interval, best);
    const Real d = ray.direction[n.axis];
    const Real p = ray.origin[n.axis] + interval.min * d;
    const bool starts_below = p < n.split || (p == n.split && d < 0);
    const BspRef near = starts_below ? n.left : n.right;
    const BspRef far = starts_below ? n.right : n.left;
    if (starts_below ? !(d > 0) : !(d < 0)) return hit_node(surfaces, near, ray, interval, best);
    const Real t = (n.split - ray.origin[n.axis]) / d;
    const Real s = slack(ray, n.axis);
    if (t - s > interval.max) return hit_node(surfaces, near, ray, interval, best);
    if (hit_node(surfaces, near, ray, Interval{interval.min, std::min(interval.max, t + s)}, best)) return true;
    return hit_node(surfaces, far, ray, interval, best);
