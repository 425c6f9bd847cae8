// fairness 5.1 pass: the closest t kept in a variable of its own, the interval rebuilt for each surface
// @body
    Real closest = interval.max;
    bool found = false;
    for (const Surface& surface : surfaces_)
        if (surface.hit(ray, Interval{interval.min, closest}, rec)) {
            closest = rec.t;
            found = true;
        }
    return found;
