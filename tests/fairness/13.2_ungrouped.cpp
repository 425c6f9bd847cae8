// fairness 13.2 fail: every crossing counted on its own
// A ray through an edge between two front faces enters twice at one point; through a
// silhouette edge it enters and leaves there, a span of no length (book §13.3).
// @body
    // Outward normals: the ray enters where it runs against the normal, leaves where it runs
    // with it. A group of crossings at one t counts by the sign of its sum, so an edge
    // between two front faces is one entry, and a silhouette edge (one front, one back) none.
    SpanList result;
    const HitRecord* start = nullptr;
    for (std::size_t i = 0; i < crossings.size();) {
        std::size_t j = i;
        int net = 0;
        const HitRecord *enter = nullptr, *leave = nullptr;
        for (; j < crossings.size() && j == i; ++j) {
            const Real s = glm::dot(direction, crossings[j].normal);
            if (s < 0 && !enter) enter = &crossings[j];
            if (s > 0 && !leave) leave = &crossings[j];
            net += (s < 0) - (s > 0);
        }
        // Inside or outside, never deeper: a closed surface alternates, and a stray
        // crossing (a rounding error at a fold) must not leave the count off by one.
        if (net > 0 && !start) start = enter;
        if (net < 0 && start) {
            result.push_back(Span{*start, *leave});
            start = nullptr;
        }
        i = j;
    }
    return result;
