// Book §13.1-13.2, course Figures 9.25-9.26: a circle C and a square S (a sphere and a box
// cut by the plane z = 0), a ray through both, and the spans along it. The operands' spans
// come from the library's spans() (the whole line), the results from exercise 13.1's
// combine(): union, intersection and difference. Each row of bars sits under the stretch of
// the ray it stands for; the first end at t >= 0 of the last row is what the ray hits.
#include "geometry/shape.hpp"
#include "kinds.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace figures {

Canvas csg_spans(const rt::Fields& in) {
    const rt::Fields cf = in.object("circle");
    const rt::Sphere circle(cf.vec3("center"), cf.length("radius"));
    cf.done();
    const rt::Fields sf = in.object("square");
    const rt::Cuboid square(sf.vec3("min"), sf.vec3("max"));
    sf.done();
    const auto [ray, t_end] = ray_of(in);
    if (ray.direction.x <= 0) in.fail("ray", "must move towards +x: its bars are laid out along x");

    rt::SpanList a, b;
    rt::spans(rt::Shape(circle), ray, a);
    rt::spans(rt::Shape(square), ray, b);
    if (a.empty() || b.empty()) in.fail("ray", "must pass through both shapes");

    Canvas c;
    c.circle(flat(circle.center), double(circle.radius), Ink::surface);
    c.box(flat(square.min), flat(square.max), Ink::surface);
    c.circle(flat(circle.center), double(circle.radius), Ink::surface, false, Stroke::dashed);  // seen through S
    c.label(flat(circle.center) + P2{-0.7 * double(circle.radius), 0.7 * double(circle.radius)}, "C", Ink::axis, -4, 4,
            Anchor::end);
    c.label(P2{double(square.max.x), double(square.max.y)}, "S", Ink::axis, 4, 4);
    c.arrow(flat(ray.origin), flat(ray.at(t_end)), Ink::camera);
    c.dot(flat(ray.origin), Ink::camera);
    c.label(flat(ray.origin), "e", Ink::camera, -8, 4, Anchor::end);

    const double size = double(circle.radius);
    const double row = 0.42 * size, bar = 0.07 * size;
    const double top = std::min(double(circle.center.y - circle.radius), double(square.min.y)) - 0.5 * size;
    const double left = double(ray.origin.x);
    struct Row {
        std::string name;
        rt::SpanList spans;
    };
    const std::vector<Row> rows{{"C", a},
                                {"S", b},
                                {"C ∪ S", rt::combine(rt::CsgOp::union_of, a, b)},
                                {"C ∩ S", rt::combine(rt::CsgOp::intersection, a, b)},
                                {"C − S", rt::combine(rt::CsgOp::difference, a, b)}};
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const double y = top - row * double(k);
        c.label(P2{left, y}, rows[k].name, Ink::axis, -4, -5, Anchor::end, true);
        c.line(P2{left, y}, P2{double(ray.at(t_end).x), y}, Ink::guide, Stroke::thin);
        for (const rt::Span& s : rows[k].spans) {
            const double x0 = double(s.in.p.x), x1 = double(s.out.p.x);
            c.box(P2{x0, y - bar}, P2{x1, y + bar}, k < 2 ? Ink::surface : Ink::camera);
        }
        if (rows[k].spans.empty()) c.label(P2{left, y}, "empty", Ink::axis, 8, -5, Anchor::start, true);
    }
    // The hit of C − S: the first end of its spans at t >= 0, the record exercise 13.1 copied.
    for (const rt::Span& s : rows.back().spans) {
        const rt::HitRecord* h = s.in.t >= 0 ? &s.in : s.out.t >= 0 ? &s.out : nullptr;
        if (!h) continue;
        c.dot(flat(h->p), Ink::hit);
        c.label(flat(h->p), "C − S is hit here", Ink::hit, 6, 8, Anchor::start, true);
        break;
    }
    return c;
}

}  // namespace figures
