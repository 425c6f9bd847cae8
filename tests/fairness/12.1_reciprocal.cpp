// fairness 12.1 pass: the plane's t and the slack from one reciprocal of d, as §12.7 suggests
// Each comes out within a unit in the last place of the book's form: the same hits, and the
// same nodes visited (the counts differ only if a part's end falls within an ulp of a
// plane's, which no ray of the tests does).
// @body
    const BspNode& n = node(ref);
    if (n.leaf()) return hit_leaf(surfaces, n, ray, interval, best);
    const Real d = ray.direction[n.axis];
    const Real p = ray.origin[n.axis] + interval.min * d;
    const bool starts_below = p < n.split || (p == n.split && d < 0);
    const BspRef near = starts_below ? n.left : n.right;
    const BspRef far = starts_below ? n.right : n.left;
    if (starts_below ? !(d > 0) : !(d < 0)) return hit_node(surfaces, near, ray, interval, best);
    const Real inv = 1 / d;  // one division where the book's form has two
    const Real t = (n.split - ray.origin[n.axis]) * inv;
    const Real s = pad() * std::abs(inv);
    if (t - s > interval.max) return hit_node(surfaces, near, ray, interval, best);
    if (hit_node(surfaces, near, ray, Interval{interval.min, std::min(interval.max, t + s)}, best)) return true;
    return hit_node(surfaces, far, ray, Interval{std::max(interval.min, t - s), interval.max}, best);
