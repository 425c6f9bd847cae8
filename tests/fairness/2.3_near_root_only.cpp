// fairness 2.3 fail: the near root or nothing
// Right for every sphere in front of the eye; an eye inside a sphere sees nothing.
// @body
    Real t_near, t_far;
    if (!sphere_roots(ray, sphere.center, sphere.radius, t_near, t_far)) return false;
    if (!interval.contains(t_near)) return false;
    result = SphereHit{t_near};
    return true;
