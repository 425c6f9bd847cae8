// fairness 2.3 fail: a near root past max falls back to the far root without checking max
// The far root is even farther: once the near one is past max, so is the sphere.
// @body
    Real t_near, t_far;
    if (!sphere_roots(ray, sphere.center, sphere.radius, t_near, t_far)) return false;
    if (interval.contains(t_near)) {
        result = SphereHit{t_near};
        return true;
    }
    if (t_far >= interval.min) {
        result = SphereHit{t_far};
        return true;
    }
    return false;
