#pragma once
// What the two grid figures (book §11.3) share: a grid seen along one axis, its planes drawn
// where the library puts them (Grid::boundary), and the cells a ray's walk visits, stepped
// by the library's own start (exercise 11.1) and next.
#include "accel/grid.hpp"
#include "kinds.hpp"

#include <algorithm>
#include <array>
#include <vector>

namespace figures {

// The grid seen along the axis that is neither `a` nor `b`: world (p[a], p[b]).
struct GridView {
    int a = 0, b = 1;
    P2 operator()(const rt::Vec3& p) const { return {double(p[a]), double(p[b])}; }
};

// Where the walk is in each cell it enters: the cell and the t at which it enters it.
struct WalkStep {
    std::array<int, 3> cell;
    rt::Real t_in;
};

inline std::vector<WalkStep> walk_cells(const rt::Grid& grid, const rt::Ray& ray, rt::Interval interval) {
    std::vector<WalkStep> steps;
    rt::GridWalk walk;
    if (!grid.start(ray, interval, walk)) return steps;
    rt::Interval clipped = interval;
    grid.clip(ray, clipped);
    steps.push_back({walk.cell, clipped.min});
    for (;;) {
        const rt::Real t_next = std::min(walk.t_max.x, std::min(walk.t_max.y, walk.t_max.z));
        if (!grid.next(ray, walk)) break;
        steps.push_back({walk.cell, t_next});
    }
    return steps;
}

// A cell's rectangle in the view.
inline void cell_corners(const rt::Grid& grid, const GridView& v, const std::array<int, 3>& cell, P2& lo, P2& hi) {
    lo = {double(grid.boundary(v.a, cell[v.a])), double(grid.boundary(v.b, cell[v.b]))};
    hi = {double(grid.boundary(v.a, cell[v.a] + 1)), double(grid.boundary(v.b, cell[v.b] + 1))};
}

// The grid's planes across the two axes of the view, as thin lines.
inline void grid_lines(Canvas& c, const rt::Grid& grid, const GridView& v) {
    const auto& n = grid.resolution();
    const double a0 = double(grid.boundary(v.a, 0)), a1 = double(grid.boundary(v.a, n[v.a]));
    const double b0 = double(grid.boundary(v.b, 0)), b1 = double(grid.boundary(v.b, n[v.b]));
    for (int k = 0; k <= n[v.a]; ++k) {
        const double x = double(grid.boundary(v.a, k));
        c.line({x, b0}, {x, b1}, Ink::surface, Stroke::thin);
    }
    for (int k = 0; k <= n[v.b]; ++k) {
        const double y = double(grid.boundary(v.b, k));
        c.line({a0, y}, {a1, y}, Ink::surface, Stroke::thin);
    }
}

// "xy", "xz" or "yz": the plane a figure shows.
inline GridView grid_view(const rt::Fields& in) {
    const std::string name = in.text("view", "xy");
    if (name == "xy") return {0, 1};
    if (name == "xz") return {0, 2};
    if (name == "yz") return {1, 2};
    in.fail("view", "must be \"xy\", \"xz\" or \"yz\", not \"" + name + "\"");
}

}  // namespace figures
