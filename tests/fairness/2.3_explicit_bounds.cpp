// fairness 2.3 pass: the interval's ends compared by hand, min <= t <= max
// @body
    Real t_near, t_far;
    if (!sphere_roots(ray, sphere.center, sphere.radius, t_near, t_far)) return false;
    Real t = t_near;
    if (t < interval.min || t > interval.max) t = t_far;
    if (t < interval.min || t > interval.max) return false;
    result.t = t;
    return true;
