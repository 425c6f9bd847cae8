// fairness 12.1 fail: the far side searched even after a hit on the near side
// best keeps the closer hit, so the answer is right, but the plane orders the sides: a hit
// on the near side comes before anything on the far side, which need not be opened.
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
    const bool on_near = hit_node(surfaces, near, ray, Interval{interval.min, std::min(interval.max, t + s)}, best);
    const bool on_far = hit_node(surfaces, far, ray, Interval{std::max(interval.min, t - s), interval.max}, best);
    return on_near || on_far;
