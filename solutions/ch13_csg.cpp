// Chapter 13 exercises: constructive solid geometry (book §13, course §9.10). Declared in
// common/geometry/csg.hpp.
#include "core/exercise.hpp"
#include "geometry/csg.hpp"

#include <algorithm>

namespace rt {

// @book combine
SpanList combine(CsgOp op, const SpanList& a, const SpanList& b) {
    // @exercise 13.1 | combine | book §13.2
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
        return x.in && !y.in;
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
    // @end
}
// @book-end

// @book mesh-spans
SpanList mesh_spans(const std::vector<HitRecord>& crossings, const Vec3& direction, Real same_t) {
    // @exercise 13.2 | mesh_spans | book §13.3
    // Outward normals: the ray enters where it runs against the normal, leaves where it runs
    // with it. A group of crossings at one t counts by the sign of its sum, so an edge
    // between two front faces is one entry, and a silhouette edge (one front, one back) none.
    SpanList result;
    const HitRecord* start = nullptr;
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
        if (net > 0 && !start) start = enter;
        if (net < 0 && start) {
            result.push_back(Span{*start, *leave});
            start = nullptr;
        }
        i = j;
    }
    return result;
    // @end
}
// @book-end

}  // namespace rt
