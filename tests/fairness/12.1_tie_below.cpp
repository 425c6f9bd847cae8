// fairness 12.1 pass: a part that starts exactly on the plane counts as below it, whichever way it moves
// The contract leaves the side free: both parts reach the slack past the plane, so either
// order finds the same hits with the same visits away from ties (book §12.2).
// @body
    const BspNode& n = node(ref);
    if (n.leaf()) return hit_leaf(surfaces, n, ray, interval, best);
    const Real d = ray.direction[n.axis];
    const Real p = ray.origin[n.axis] + interval.min * d;
    const bool starts_below = p <= n.split;
    const BspRef near = starts_below ? n.left : n.right;
    const BspRef far = starts_below ? n.right : n.left;
    if (starts_below ? !(d > 0) : !(d < 0)) return hit_node(surfaces, near, ray, interval, best);
    const Real t = (n.split - ray.origin[n.axis]) / d;
    const Real s = slack(ray, n.axis);
    if (t - s > interval.max) return hit_node(surfaces, near, ray, interval, best);
    if (hit_node(surfaces, near, ray, Interval{interval.min, std::min(interval.max, t + s)}, best)) return true;
    return hit_node(surfaces, far, ray, Interval{std::max(interval.min, t - s), interval.max}, best);
