// fairness 5.1 fail: the best record kept in a local and copied out even when nothing was hit
// A miss must leave rec alone: the caller may pass in a hit of its own.
// @body
    HitRecord best;
    bool found = false;
    for (const Surface& surface : surfaces_)
        if (surface.hit(ray, interval, best)) {
            found = true;
            interval.max = best.t;
        }
    rec = best;
    return found;
