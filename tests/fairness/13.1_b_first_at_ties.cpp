// fairness 13.1 pass: at equal t, among entries (or among exits), b's ends before a's
// Which of two ends of one kind at one t comes first decides only which record a result
// span takes there, and both are ends of the result's surface: the contract leaves it free.
// @body
    // Walk the ends of all spans in order of t, counting how deep inside a and b the ray is;
    // a result span starts where `op` becomes true and ends where it becomes false.
    struct End {
        const HitRecord* rec;
        int side;  // 0: a, 1: b
        bool in;
    };
    std::vector<End> ends;
    ends.reserve(2 * (a.size() + b.size()));
    for (int side = 0; side < 2; ++side)
        for (const Span& s : side == 0 ? a : b) {
            ends.push_back(End{&s.in, side, true});
            ends.push_back(End{&s.out, side, false});
        }
    // At equal t, entering before leaving: two solids that touch make one span of a union,
    // and a span of no thickness in an intersection (which drop_thin removes).
    std::stable_sort(ends.begin(), ends.end(), [](const End& x, const End& y) {
        if (x.rec->t != y.rec->t) return x.rec->t < y.rec->t;
        if (x.in != y.in) return x.in;
        return x.side > y.side;
    });
    SpanList result;
    int depth[2] = {0, 0};
    bool inside = false;
    const HitRecord* start = nullptr;
    for (const End& e : ends) {
        depth[e.side] += e.in ? 1 : -1;
        const bool in_a = depth[0] > 0, in_b = depth[1] > 0;
        const bool now = op == CsgOp::union_of       ? in_a || in_b
                         : op == CsgOp::intersection ? in_a && in_b
                                                     : in_a && !in_b;
        if (now && !inside) start = e.rec;
        if (!now && inside) result.push_back(Span{*start, *e.rec});
        inside = now;
    }
    return result;
