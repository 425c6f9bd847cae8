// fairness 5.1 fail: the first surface hit, not the closest (what a shadow ray needs, not a camera ray)
// @body
    for (const Surface& surface : surfaces_)
        if (surface.hit(ray, interval, rec)) return true;
    return false;
