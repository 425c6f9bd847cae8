// fairness 5.1 fail: the interval never shrinks, so rec ends up as the last surface hit
// Right when the surfaces happen to be listed from far to near.
// @body
    bool found = false;
    for (const Surface& surface : surfaces_)
        if (surface.hit(ray, interval, rec)) found = true;
    return found;
