// Book §4.3: the crossing-number test. From each point a ray runs along +x; the edges it
// crosses are marked, and the point is inside when their number is odd. An edge counts when
// its ends lie on opposite sides of the ray's line, with "above" meaning strictly above: a
// vertex on the line belongs to the edges above it only, so it is counted once (or not at
// all), never twice. The inside/outside answer is inside_polygon_2d's (exercise 4.2); the
// marks are counted here by the same rule, and a figure whose count disagrees with the
// library's answer is refused rather than drawn.
#include "geometry/polygon.hpp"
#include "kinds.hpp"

#include <algorithm>

namespace figures {

Canvas crossing_rule(const rt::Fields& in) {
    const std::vector<rt::Vec3> corners = in.points("polygon", rt::limits::polygon_vertices);
    std::vector<rt::Vec2> polygon;
    double left = 1e300, right = -1e300;
    for (const rt::Vec3& p : corners) {
        polygon.emplace_back(p.x, p.y);
        left = std::min(left, double(p.x));
        right = std::max(right, double(p.x));
    }
    Canvas c;
    std::vector<P2> outline;
    for (const rt::Vec2& p : polygon) outline.push_back({double(p.x), double(p.y)});
    c.polygon(outline, Ink::surface);

    const auto points = in.points("points", {"points", 1, 16, "", ""});
    for (std::size_t k = 0; k < points.size(); ++k) {
        const rt::Vec2 p(points[k].x, points[k].y);
        const P2 from{double(p.x), double(p.y)}, to{right + 0.15 * (right - left), double(p.y)};
        c.arrow(from, to, Ink::camera, Stroke::thin);
        int crossings = 0;
        std::vector<double> marks;
        for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
            const rt::Vec2 &a = polygon[i], &b = polygon[j];
            if ((a.y > p.y) != (b.y > p.y)) {
                const rt::Real x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
                if (x > p.x) {
                    ++crossings;
                    // Two edges crossed at one place (a vertex): one mark, labelled x2.
                    if (std::count(marks.begin(), marks.end(), double(x)))
                        c.label({double(x), double(p.y)}, "×2", Ink::camera, 0, 10, Anchor::middle, true);
                    marks.push_back(double(x));
                    c.dot({double(x), double(p.y)}, Ink::camera, true);
                }
            }
        }
        const bool inside = rt::inside_polygon_2d(polygon, p);
        if (inside != (crossings % 2 == 1))
            in.fail("points", "point " + std::to_string(k) + ": the library says " + (inside ? "inside" : "outside") +
                                  " but " + std::to_string(crossings) + " crossings were counted");
        c.dot(from, Ink::hit, !inside);
        c.label(to,
                std::to_string(crossings) + (crossings == 1 ? " crossing: " : " crossings: ") +
                    (inside ? "inside" : "outside"),
                Ink::axis, 6, -6, Anchor::start, true);
    }
    return c;
}

}  // namespace figures
