// Book §11.3: the cells a ray visits in a uniform grid. The cells come from the library's own
// walk (Grid::start, exercise 11.1, and Grid::next); how many of them the search opens before
// it stops is what Grid::walk (exercise 11.2) counts in traversal_tally. Shaded blue: the
// cells searched; dashed: the cells the ray would cross after the hit. The dots are where the
// ray crosses a plane, evenly spaced along each axis (course Figure 9.21).
#include "accel/surface_list.hpp"
#include "geometry/sphere.hpp"
#include "grid_view.hpp"

#include <string>
#include <vector>

namespace figures {

Canvas grid_walk(const rt::Fields& in) {
    const GridView view = grid_view(in);
    rt::SurfaceList list;
    const std::vector<rt::Sphere> spheres = spheres_of(in);
    for (const rt::Sphere& s : spheres) list.add(s);
    if (spheres.empty()) in.fail("spheres", "needs at least one sphere");
    const rt::Grid grid(list, in.number("density", {"density", 0.01, 1000, "", ""}));
    const auto [ray, t_end] = ray_of(in);

    const std::vector<WalkStep> steps = walk_cells(grid, ray, rt::Interval{});
    if (steps.empty()) in.fail("ray", "misses the grid");
    rt::traversal_tally = {};
    rt::HitRecord best = rt::no_hit_before(rt::kInfinity);
    const bool hit = grid.walk(list, ray, rt::Interval{}, best);
    const std::size_t searched = std::size_t(rt::traversal_tally.nodes);
    rt::HitRecord brute;
    if (hit != list.hit(ray, rt::Interval{}, brute) || (hit && brute.t != best.t))
        in.fail("ray", "the grid's walk disagrees with brute force");

    Canvas c;
    for (std::size_t k = 0; k < steps.size(); ++k) {
        P2 lo, hi;
        cell_corners(grid, view, steps[k].cell, lo, hi);
        if (k < searched)
            c.box(lo, hi, Ink::camera);
        else
            c.polygon({lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}, Ink::camera, false, Stroke::dashed);
    }
    grid_lines(c, grid, view);
    for (const rt::Sphere& s : spheres) c.circle(view(s.center), double(s.radius), Ink::surface);
    c.arrow(view(ray.origin), view(ray.at(t_end)), Ink::camera);
    c.dot(view(ray.origin), Ink::camera);
    c.label(view(ray.origin), "e", Ink::camera, -8, 4, Anchor::end);
    for (std::size_t k = 1; k < steps.size(); ++k) c.dot(view(ray.at(steps[k].t_in)), Ink::axis, true);
    if (hit) {
        c.dot(view(best.p), Ink::hit);
        c.label(view(best.p), "hit in cell " + std::to_string(searched), Ink::hit, 4, -24);
    }
    const auto& n = grid.resolution();
    c.label(P2{double(grid.boundary(view.a, 0)), double(grid.boundary(view.b, 0))},
            std::to_string(n[view.a]) + " × " + std::to_string(n[view.b]) + " cells; the ray crosses " +
                std::to_string(steps.size()) + ", the search opens " + std::to_string(searched),
            Ink::axis, 0, -22, Anchor::start, true);
    return c;
}

}  // namespace figures
