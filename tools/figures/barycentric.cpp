// Book §3.1-3.2: barycentric coordinates. A point is a + beta (b - a) + gamma (c - a); it is
// in the triangle when beta >= 0, gamma >= 0 and beta + gamma <= 1, and each of the three
// lines where one of them is zero carries an edge. Each point of the description is given
// by its (beta, gamma); a ray straight down onto it asks ray_triangle (exercise 3.1), and
// the label says what the library found: the coordinates of a hit, or a miss.
#include "geometry/triangle.hpp"
#include "kinds.hpp"

namespace figures {

Canvas barycentric(const rt::Fields& in) {
    const std::vector<rt::Vec3> v = in.points("vertices", rt::limits::triangle_vertices);
    const rt::Vec3 &a = v[0], &b = v[1], &c = v[2];
    if (a.z != 0 || b.z != 0 || c.z != 0) in.fail("vertices", "must lie in the plane z = 0 (the page)");
    const rt::Triangle triangle(a, b, c);  // refuses a degenerate one
    const rt::Real extend =
        in.number("extend", {"extension", 0, 4, "", ""});  // how far past the corners the edge lines go

    Canvas cv;
    // The three lines beta = 0 (through a and c), gamma = 0 (a, b) and beta + gamma = 1 (b, c),
    // drawn past the triangle, each labelled on the side where its coordinate is negative.
    const auto edge_line = [&](const rt::Vec3& p, const rt::Vec3& q, const std::string& name) {
        cv.line(flat(p + extend * (p - q)), flat(q + extend * (q - p)), Ink::guide, Stroke::dashed);
        cv.label(flat(q + extend * (q - p)), name, Ink::guide, 6, 6);
    };
    cv.polygon({flat(a), flat(b), flat(c)}, Ink::surface);
    edge_line(a, c, "β = 0");
    edge_line(a, b, "γ = 0");
    edge_line(b, c, "β + γ = 1");
    cv.label(flat(a), "a", Ink::axis, -8, -8, Anchor::end);
    cv.label(flat(b), "b", Ink::axis, 8, -8);
    cv.label(flat(c), "c", Ink::axis, 0, 10, Anchor::middle);

    for (const rt::Fields& pt : in.objects("points")) {
        const rt::Real beta = pt.number("beta", rt::limits::coordinate),
                       gamma = pt.number("gamma", rt::limits::coordinate);
        const bool decompose = pt.flag("decompose", false);  // draw a -> a + beta (b - a) -> the point
        pt.done();
        const rt::Vec3 p = a + beta * (b - a) + gamma * (c - a);
        const rt::Ray down{p + rt::Vec3(0, 0, 1), rt::Vec3(0, 0, -1)};
        rt::TriangleHit h;
        if (rt::ray_triangle(down, a, b, c, rt::Interval{0, rt::kInfinity}, h)) {
            if (decompose) {
                const rt::Vec3 along_b = a + h.beta * (b - a);
                cv.arrow(flat(a), flat(along_b), Ink::axis);
                cv.arrow(flat(along_b), flat(down.at(h.t)), Ink::axis);
                cv.label(0.5 * (flat(a) + flat(along_b)), "β(b − a)", Ink::axis, 0, -22, Anchor::middle);
                cv.label(0.5 * (flat(along_b) + flat(down.at(h.t))), "γ(c − a)", Ink::axis, 8, 0);
            }
            cv.dot(flat(down.at(h.t)), Ink::hit);
            cv.label(flat(down.at(h.t)), "β = " + number(double(h.beta), 2) + ", γ = " + number(double(h.gamma), 2),
                     Ink::hit, 8, 6, Anchor::start, true);
        } else {
            std::string why = beta < 0 ? "β < 0" : gamma < 0 ? "γ < 0" : "β + γ > 1";
            cv.dot(flat(p), Ink::hit, true);
            cv.label(flat(p), why + ": miss", Ink::axis, 8, 6, Anchor::start, true);
        }
    }
    return cv;
}

}  // namespace figures
