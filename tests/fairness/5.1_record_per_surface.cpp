// fairness 5.1 pass: each surface tested into a record of its own, kept when it is at least as close
// Every surface is asked about the whole interval; a hit at t <= the best so far replaces it,
// so at equal t the later surface wins, as the contract says.
// @body
    bool found = false;
    for (std::size_t k = 0; k < surfaces_.size(); ++k) {
        HitRecord candidate;
        if (surfaces_[k].hit(ray, interval, candidate) && (!found || candidate.t <= rec.t)) {
            rec = candidate;
            found = true;
        }
    }
    return found;
