// Book §11.3, course Figure 9.23: why a grid's walk may accept only hits inside the current
// cell. A primitive listed in the first cell (here a triangle whose box spans the grid) is
// hit far beyond that cell; a closer primitive lies in a cell between. The library's
// walk_unchecked, which takes any hit where it finds one, returns the far hit (b); Grid::hit
// returns the near one (a), as brute force does. Both answers are the library's.
#include "accel/surface_list.hpp"
#include "geometry/sphere.hpp"
#include "geometry/triangle.hpp"
#include "grid_view.hpp"

#include <vector>

namespace figures {

Canvas grid_trap(const rt::Fields& in) {
    const GridView view = grid_view(in);
    const std::vector<rt::Vec3> corners = in.points("triangle", rt::limits::triangle_vertices);
    const rt::Fields s = in.object("sphere");
    const rt::Sphere ball(s.vec3("center"), s.length("radius"));
    s.done();
    rt::SurfaceList list;
    const rt::SurfaceId tilted = list.add(rt::Triangle(corners[0], corners[1], corners[2]));
    const rt::SurfaceId sphere = list.add(ball);
    const rt::Grid grid(list, in.number("density", {"density", 0.01, 1000, "", ""}));
    const auto [ray, t_end] = ray_of(in);

    rt::HitRecord wrong = rt::no_hit_before(rt::kInfinity), right;
    if (!grid.walk_unchecked(list, ray, rt::Interval{}, wrong) || wrong.surface != tilted)
        in.fail("triangle", "the unchecked walk must find the triangle first: no trap here");
    if (!grid.hit(list, ray, rt::Interval{}, right) || right.surface != sphere)
        in.fail("sphere", "the grid must find the sphere: it is not in front of the triangle");
    const std::vector<WalkStep> steps = walk_cells(grid, ray, rt::Interval{});

    Canvas c;
    P2 lo, hi;
    cell_corners(grid, view, steps.front().cell, lo, hi);
    c.box(lo, hi, Ink::camera);
    c.label(P2{lo.x, hi.y}, "first cell", Ink::camera, 0, 6, Anchor::start, true);
    grid_lines(c, grid, view);
    c.polygon({view(corners[0]), view(corners[1]), view(corners[2])}, Ink::surface);
    c.circle(view(ball.center), double(ball.radius), Ink::surface);
    c.arrow(view(ray.origin), view(ray.at(t_end)), Ink::camera);
    c.dot(view(ray.origin), Ink::camera);
    c.label(view(ray.origin), "e", Ink::camera, -8, 4, Anchor::end);
    c.dot(view(wrong.p), Ink::hit, true);
    c.label(view(wrong.p), "b: t = " + number(double(wrong.t)), Ink::hit, 8, 8, Anchor::start, true);
    c.dot(view(right.p), Ink::hit);
    c.label(view(right.p), "a: t = " + number(double(right.t)), Ink::hit, -8, -22, Anchor::end, true);
    return c;
}

}  // namespace figures
