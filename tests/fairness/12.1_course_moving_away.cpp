// fairness 12.1 fail: "moving away" tested as d < 0 below the plane and d > 0 above, with the slack and the clamps
// For d = -0 below the plane (or +0 above), t = -infinity and the slack is infinity: t + s
// is NaN and t - s is -infinity, std::min and std::max hand back the whole part, and the
// far side is searched over it. No wrong hit, but a side the ray never reaches is opened for nothing
// (book §12.2): the visit counts show it.
// @body
    const BspNode& n = node(ref);
    if (n.leaf()) return hit_leaf(surfaces, n, ray, interval, best);
    const Real d = ray.direction[n.axis];
    const Real p = ray.origin[n.axis] + interval.min * d;
    const bool starts_below = p < n.split || (p == n.split && d < 0);
    const BspRef near = starts_below ? n.left : n.right;
    const BspRef far = starts_below ? n.right : n.left;
    if (starts_below ? d < 0 : d > 0) return hit_node(surfaces, near, ray, interval, best);
    const Real t = (n.split - ray.origin[n.axis]) / d;
    const Real s = slack(ray, n.axis);
    if (t - s > interval.max) return hit_node(surfaces, near, ray, interval, best);
    if (hit_node(surfaces, near, ray, Interval{interval.min, std::min(interval.max, t + s)}, best)) return true;
    return hit_node(surfaces, far, ray, Interval{std::max(interval.min, t - s), interval.max}, best);
