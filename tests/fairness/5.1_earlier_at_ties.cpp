// fairness 5.1 fail: a later hit replaces the best only when strictly closer
// The closest hit still wins, but at exactly equal t the earlier surface does: the header's
// rule is the later one (what shrinking max to each t, the interval closed, gives).
// @body
    bool found = false;
    for (const Surface& surface : surfaces_) {
        HitRecord candidate;
        if (surface.hit(ray, interval, candidate) && (!found || candidate.t < rec.t)) {
            rec = candidate;
            found = true;
        }
    }
    return found;
