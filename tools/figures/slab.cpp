// Book §10.1: the slab test in 2D, a panel per ray. Each slab's range of t is what the
// library's clip_to_box keeps of the ray's interval against that slab alone (a box without
// bounds across the other axis), and the box's range is clip_to_box against the box itself,
// which exercise 10.1's hit_box must agree with (checked here too). Below each panel, the
// three ranges on one line of t: the box is entered where they overlap.
#include "accel/course_bvh.hpp"
#include "kinds.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

namespace figures {

namespace {

// The part of [0, t_end] the ray spends inside `box`, as the library clips it.
std::optional<rt::Interval> inside(const rt::Box& box, const rt::Ray& ray, rt::Real t_end) {
    rt::Interval part{0, t_end};
    if (!rt::clip_to_box(box, ray, part)) return std::nullopt;
    return part;
}

}  // namespace

Canvas slab(const rt::Fields& in) {
    const rt::Vec3 lo = in.vec3("min"), hi = in.vec3("max");
    if (!(lo.x < hi.x && lo.y < hi.y)) in.fail("max", "must exceed min in x and in y");
    const rt::Box box{rt::Vec3(lo.x, lo.y, -1), rt::Vec3(hi.x, hi.y, 1)};
    constexpr rt::Real kWide = 1e6;  // "no bound" across the other axis, finite to keep 0 * inf out
    const rt::Box x_slab{rt::Vec3(lo.x, -kWide, -kWide), rt::Vec3(hi.x, kWide, kWide)};
    const rt::Box y_slab{rt::Vec3(-kWide, lo.y, -kWide), rt::Vec3(kWide, hi.y, kWide)};

    Canvas c;
    const double w = double(hi.x - lo.x), h = double(hi.y - lo.y);
    const double margin = 0.9 * std::max(w, h);
    const double panel = w + 2 * margin, gap = 0.35 * panel;
    double left = double(lo.x) - margin;
    for (const rt::Fields& r : in.objects("rays")) {
        const rt::Ray ray{r.vec3("origin"), r.direction("direction")};
        const rt::Real t_end = r.length("t_end");
        const std::string name = r.text("label");
        r.done();
        const P2 shift{left - (double(lo.x) - margin), 0};
        auto at = [&](rt::Real t) { return flat(ray.at(t)) + shift; };
        const double top = double(hi.y) + margin, bottom = double(lo.y) - margin;
        // The slabs' planes, then the box they share.
        for (double x : {double(lo.x), double(hi.x)})
            c.line(P2{x, bottom} + shift, P2{x, top} + shift, Ink::guide, Stroke::dashed);
        for (double y : {double(lo.y), double(hi.y)})
            c.line(P2{double(lo.x) - margin, y} + shift, P2{double(hi.x) + margin, y} + shift, Ink::guide,
                   Stroke::dashed);
        c.box(P2{double(lo.x), double(lo.y)} + shift, P2{double(hi.x), double(hi.y)} + shift, Ink::surface);
        c.label(P2{double(lo.x), bottom} + shift, "x slab", Ink::axis, 4, 4, Anchor::start, true);
        c.label(P2{double(lo.x) - margin, double(hi.y)} + shift, "y slab", Ink::axis, 2, 6, Anchor::start, true);
        c.arrow(at(0), at(t_end), Ink::camera);
        c.dot(at(0), Ink::camera);
        c.label(at(0), "e", Ink::camera, -8, 4, Anchor::end);

        const auto x = inside(x_slab, ray, t_end), y = inside(y_slab, ray, t_end), both = inside(box, ray, t_end);
        const bool cull = rt::hit_box(box, ray, rt::Interval{0, t_end});
        if (cull != both.has_value()) r.fail("direction", "exercise 10.1's hit_box disagrees with clip_to_box");
        for (const auto& part : {x, y})
            if (part) {
                c.dot(at(part->min), Ink::axis, true);
                c.dot(at(part->max), Ink::axis, true);
            }
        // The line of t under the panel: t = 0 at its left end, t_end at its right.
        const double y0 = bottom - 0.25 * margin, row = 0.28 * margin, bar = 0.07 * margin;
        auto tx = [&](rt::Real t) { return left + panel * double(t / t_end); };
        c.arrow(P2{left, y0}, P2{left + panel, y0}, Ink::axis, Stroke::thin);
        c.label(P2{left + panel, y0}, "t", Ink::axis, 0, 6, Anchor::end, true);
        int k = 1;
        for (const auto& [part, what] : {std::pair{x, "x"}, std::pair{y, "y"}, std::pair{both, "box"}}) {
            const double yr = y0 - row * k++;
            c.label(P2{left, yr}, what, Ink::axis, -6, -5, Anchor::end, true);
            if (!part) {
                c.label(P2{left + panel / 2, yr}, "empty: enters after it leaves", Ink::axis, 0, -5, Anchor::middle,
                        true);
                continue;
            }
            const Ink ink = std::string(what) == "box" ? Ink::camera : Ink::surface;
            c.box(P2{tx(part->min), yr - bar}, P2{tx(part->max), yr + bar}, ink);
            if (std::string(what) == "box") {
                c.dot(at(part->min), Ink::hit);
                c.dot(at(part->max), Ink::hit);
            }
        }
        c.label(P2{left + panel / 2, y0 - row * 4}, name + (both ? ": a hit" : ": a miss"), Ink::axis, 0, -4,
                Anchor::middle);
        left += panel + gap;
    }
    return c;
}

}  // namespace figures
