// fairness 12.1 fail: the parts end and start exactly at the plane (no slack)
// A hit that rounding puts just past the plane is refused on the near side, and two hits at
// one t on an edge in the plane can be split between the sides (book §12.3).
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
    const Real s = 0;
    if (t - s > interval.max) return hit_node(surfaces, near, ray, interval, best);
    if (hit_node(surfaces, near, ray, Interval{interval.min, std::min(interval.max, t + s)}, best)) return true;
    return hit_node(surfaces, far, ray, Interval{std::max(interval.min, t - s), interval.max}, best);
