// fairness 2.3 pass: a near root before min means the far one, decided before the near root is tried
// @body
    Real t_near, t_far;
    if (!sphere_roots(ray, sphere.center, sphere.radius, t_near, t_far)) return false;
    const Real t = t_near >= interval.min ? t_near : t_far;
    if (t < interval.min || t > interval.max) return false;
    result = SphereHit{t};
    return true;
