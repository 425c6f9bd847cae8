// Book §12.2, course Figure 9.24: the four ways a ray's part meets a BSP node's plane, a
// panel per ray. The tree is the library's (exercise 12.2's midpoint build over two circles,
// one each side of the root's plane x = D), and which sides the search opens is counted, not
// assumed: each ray goes through exercise 12.1's Bsp::hit_node from the root, and the nodes it
// visits (traversal_tally) say whether the far side was searched. Solid blue: searched;
// dashed grey: never opened.
#include "accel/bsp.hpp"
#include "accel/surface_list.hpp"
#include "geometry/sphere.hpp"
#include "kinds.hpp"

#include <string>
#include <vector>

namespace figures {

Canvas bsp_cases(const rt::Fields& in) {
    rt::SurfaceList list;
    const std::vector<rt::Sphere> spheres = spheres_of(in);
    for (const rt::Sphere& s : spheres) list.add(s);
    if (spheres.size() != 2) in.fail("spheres", "needs two circles, one each side of the plane");
    const rt::Bsp bsp(list, rt::BspBuild::midpoint, 1);
    const rt::BspNode root = bsp.node(bsp.root());
    if (root.leaf() || root.axis != 0 || !bsp.node(root.left).leaf() || !bsp.node(root.right).leaf())
        in.fail("spheres", "the build must cut once, across x, with one circle on each side");
    const rt::Box cell = bsp.bounding_box();
    const double D = double(root.split);
    const double width = double(cell.max.x - cell.min.x), height = double(cell.max.y - cell.min.y);
    const double gap_x = 0.35 * width, gap_y = 0.85 * height;

    Canvas c;
    int panel = 0;
    for (const rt::Fields& r : in.objects("rays")) {
        const rt::Ray ray{r.vec3("origin"), r.direction("direction")};
        const rt::Real t1 = r.length("t_end");
        const std::string name = r.text("label");
        r.done();
        const P2 shift{(panel % 2) * (width + gap_x), -(panel / 2) * (height + gap_y)};
        ++panel;
        auto at = [&](rt::Real t) { return flat(ray.at(t)) + shift; };

        c.box(P2{double(cell.min.x), double(cell.min.y)} + shift, P2{double(cell.max.x), double(cell.max.y)} + shift,
              Ink::guide, false);
        c.line(P2{D, double(cell.min.y)} + shift, P2{D, double(cell.max.y)} + shift, Ink::axis, Stroke::dashed);
        c.label(P2{D, double(cell.max.y)} + shift, "x = D", Ink::axis, 0, 6, Anchor::middle, true);
        for (const rt::Sphere& s : spheres) c.circle(flat(s.center) + shift, double(s.radius), Ink::surface);

        rt::traversal_tally = {};
        rt::HitRecord best = rt::no_hit_before(t1);
        const bool hit = bsp.hit_node(list, bsp.root(), ray, rt::Interval{0, t1}, best);
        const bool far_searched = rt::traversal_tally.nodes == 3;
        const rt::Real d = ray.direction.x;
        const rt::Real t = (root.split - ray.origin.x) / d;  // where the ray meets the plane
        const bool crosses = d != 0 && t > 0 && t < t1;
        const rt::Real end = hit ? best.t : t1;
        if (crosses) {
            c.line(at(0), at(t), Ink::camera);
            if (far_searched)
                c.arrow(at(t), at(end), Ink::camera);
            else
                c.line(at(t), at(t1), Ink::guide, Stroke::dashed);
            c.dot(at(t), Ink::axis, true);
            // Right of the crossing, on the side of the line the ray leaves free.
            const bool rising = (ray.direction.x > 0) == (ray.direction.y > 0);
            c.label(at(t), "t = " + number(double(t)), Ink::axis, 6, rising ? -16 : 4, Anchor::start, true);
        } else {
            c.arrow(at(0), at(end), Ink::camera);
        }
        c.dot(at(0), Ink::camera);
        if (hit) c.dot(flat(best.p) + shift, Ink::hit);
        const std::string outcome = hit && !far_searched && crosses ? "hit on the near side: far side not opened"
                                    : far_searched                  ? "near side, then far side"
                                                                    : "near side only";
        c.label(P2{double(cell.min.x) + width / 2, double(cell.min.y)} + shift, name, Ink::axis, 0, -20, Anchor::middle,
                true);
        c.label(P2{double(cell.min.x) + width / 2, double(cell.min.y)} + shift, outcome, Ink::camera, 0, -38,
                Anchor::middle, true);
    }
    return c;
}

}  // namespace figures
