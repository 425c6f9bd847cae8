// Book §4.2: a polygon in space is tested in 2D, after dropping the coordinate along which
// its normal is largest: that projection has the largest area and never collapses to a line.
// The normal is the Polygon's own (Newell's method), the axes kept are projection_axes'
// (exercise 4.1) and the flat copy is the Polygon's projected() vertices, drawn on the
// coordinate plane they lie in.
#include "geometry/polygon.hpp"
#include "kinds.hpp"

namespace figures {

Canvas polygon_projection(const rt::Fields& in) {
    const rt::Polygon polygon(in.points("vertices", rt::limits::polygon_vertices));
    const rt::Real axis = in.length("axis");  // how long the coordinate axes are drawn
    const View3 view(in.direction("look_from"), rt::Vec3(0, 1, 0));
    const auto kept = polygon.axes();
    const int dropped = 3 - kept[0] - kept[1];
    const char* names[] = {"x", "y", "z"};

    Canvas c;
    for (int k = 0; k < 3; ++k) {
        rt::Vec3 e(0);
        e[k] = axis;
        c.arrow(view(rt::Vec3(0)), view(e), k == dropped ? Ink::guide : Ink::axis);
        c.label(view(e), names[k], k == dropped ? Ink::guide : Ink::axis, 4, 4);
    }
    // The flat copy on the plane where the dropped coordinate is 0.
    std::vector<P2> flat_copy, outline;
    rt::Vec3 centroid(0);
    for (std::size_t k = 0; k < polygon.vertices().size(); ++k) {
        rt::Vec3 q(0);
        q[kept[0]] = polygon.projected()[k].x;
        q[kept[1]] = polygon.projected()[k].y;
        flat_copy.push_back(view(q));
        outline.push_back(view(polygon.vertices()[k]));
        centroid += polygon.vertices()[k];
        c.line(view(polygon.vertices()[k]), view(q), Ink::guide, Stroke::dashed);
    }
    centroid /= rt::Real(polygon.vertices().size());
    c.polygon(flat_copy, Ink::camera, true, Stroke::dashed);
    c.polygon(outline, Ink::surface);
    c.arrow(view(centroid), view(centroid + axis * rt::Real(0.5) * polygon.normal()), Ink::normal);
    c.label(view(centroid + axis * rt::Real(0.5) * polygon.normal()),
            "n = (" + number(double(polygon.normal().x), 2) + ", " + number(double(polygon.normal().y), 2) + ", " +
                number(double(polygon.normal().z), 2) + ")",
            Ink::normal, 6, 4, Anchor::start, true);
    P2 middle{0, 0};
    for (const P2& q : flat_copy) middle = middle + (1.0 / double(flat_copy.size())) * q;
    c.label(middle, std::string("drop ") + names[dropped] + ", keep " + names[kept[0]] + " and " + names[kept[1]],
            Ink::camera, 0, -6, Anchor::middle, true);
    return c;
}

}  // namespace figures
