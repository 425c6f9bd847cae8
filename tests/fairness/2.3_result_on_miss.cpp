// fairness 2.3 fail: the near root written to result before the interval is checked
// A miss must leave result alone: a list of surfaces passes in the closest hit so far.
// @body
    Real t_near, t_far;
    if (!sphere_roots(ray, sphere.center, sphere.radius, t_near, t_far)) return false;
    result = SphereHit{t_near};
    if (interval.contains(t_near)) return true;
    result = SphereHit{t_far};
    return interval.contains(t_far);
