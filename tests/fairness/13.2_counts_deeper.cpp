// fairness 13.2 fail: the state counts how deep inside the mesh the ray is
// A closed surface alternates: a stray extra entry made by rounding at a fold must not
// leave the count one too deep, which shifts every later span (book §13.3).
// @body
    // Outward normals: the ray enters where it runs against the normal, leaves where it runs
    // with it. A group of crossings at one t counts by the sign of its sum, so an edge
    // between two front faces is one entry, and a silhouette edge (one front, one back) none.
    SpanList result;
    const HitRecord* start = nullptr;
    int depth = 0;
    for (std::size_t i = 0; i < crossings.size();) {
        std::size_t j = i;
        int net = 0;
        const HitRecord *enter = nullptr, *leave = nullptr;
        for (; j < crossings.size() && crossings[j].t - crossings[i].t <= same_t; ++j) {
            const Real s = glm::dot(direction, crossings[j].normal);
            if (s < 0 && !enter) enter = &crossings[j];
            if (s > 0 && !leave) leave = &crossings[j];
            net += (s < 0) - (s > 0);
        }
        // Inside or outside, never deeper: a closed surface alternates, and a stray
        // crossing (a rounding error at a fold) must not leave the count off by one.
        depth += net > 0 ? 1 : (net < 0 ? -1 : 0);
        if (net > 0 && depth == 1) start = enter;
        if (net < 0 && depth == 0 && start) {
            result.push_back(Span{*start, *leave});
            start = nullptr;
        }
        i = j;
    }
    return result;
