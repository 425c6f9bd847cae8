// fairness 13.1 fail: a merge of the two lists of ends, each list's ends in its own order
// Each list is sorted, so two pointers seem enough. But two spans of one list that touch,
// [0, 2] and [2, 4], list the exit at t = 2 before the entry at t = 2: within a list the
// merge keeps exits first, and a union of such a list with nothing cuts the solid in two
// at a face that is not there. Entries come before exits at equal t in both lists at once.
// @body
    // Each list's ends are in order already: merge them, entries before exits at equal t.
    struct End {
        const HitRecord* rec;
        int side;
        bool in;
    };
    const auto end_of = [&](int side, std::size_t k) {
        const SpanList& l = side == 0 ? a : b;
        return End{k % 2 ? &l[k / 2].out : &l[k / 2].in, side, k % 2 == 0};
    };
    std::size_t i = 0, j = 0;
    const std::size_t na = 2 * a.size(), nb = 2 * b.size();
    SpanList result;
    int depth[2] = {0, 0};
    bool inside = false;
    const HitRecord* start = nullptr;
    while (i < na || j < nb) {
        bool take_a = j >= nb;
        if (i < na && j < nb) {
            const End x = end_of(0, i), y = end_of(1, j);
            take_a = x.rec->t < y.rec->t || (x.rec->t == y.rec->t && (x.in || !y.in));
        }
        const End e = take_a ? end_of(0, i++) : end_of(1, j++);
        depth[e.side] += e.in ? 1 : -1;
        const bool in_a = depth[0] > 0, in_b = depth[1] > 0;
        const bool now = op == CsgOp::union_of ? in_a || in_b : op == CsgOp::intersection ? in_a && in_b : in_a && !in_b;
        if (now && !inside) start = e.rec;
        if (!now && inside) result.push_back(Span{*start, *e.rec});
        inside = now;
    }
    return result;
