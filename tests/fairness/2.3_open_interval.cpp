// fairness 2.3 fail: the open interval (min, max) of course §9.4.1
// The book's erratum: the interval is closed, both ends count.
// @body
    Real t_near, t_far;
    if (!sphere_roots(ray, sphere.center, sphere.radius, t_near, t_far)) return false;
    for (const Real t : {t_near, t_far})
        if (t > interval.min && t < interval.max) {
            result = SphereHit{t};
            return true;
        }
    return false;
