#include "app/ray_tree_svg.hpp"

#include "core/xml.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace rt {

namespace {

struct P2 {
    double x, y;
};

// Orthographic projection onto the plane of two unit axes: `lateral` across the page,
// `forward` up the page (SVG's y grows downwards, hence the sign).
struct PageProjection {
    Vec3 origin, lateral, forward;
    P2 operator()(const Vec3& p) const {
        const Vec3 d = p - origin;
        return {double(glm::dot(d, lateral)), -double(glm::dot(d, forward))};
    }
};

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

std::string rgb(const Color& c) {
    const auto b = [](float v) { return std::to_string(int(std::lround(255 * std::clamp(v, 0.0f, 1.0f)))); };
    return "rgb(" + b(c.r) + "," + b(c.g) + "," + b(c.b) + ")";
}

std::string triple(const Color& c) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g)", double(c.r), double(c.g), double(c.b));
    return buf;
}

// Convex hull (Andrew's monotone chain): the outline of a convex body's projected points.
std::vector<P2> hull(std::vector<P2> pts) {
    std::sort(pts.begin(), pts.end(), [](P2 a, P2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    if (pts.size() < 3) return pts;
    const auto cross = [](P2 o, P2 a, P2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
    std::vector<P2> h(2 * pts.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
        h[k++] = pts[i];
    }
    for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && cross(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
        h[k++] = pts[i];
    }
    h.resize(k - 1);
    return h;
}

std::string polygon(const std::vector<P2>& pts, const char* style) {
    std::string s = "<polygon points=\"";
    for (const P2& p : pts) s += num(p.x) + "," + num(p.y) + " ";
    return s + "\" " + style + "/>\n";
}

// The outlines of one shape, seen through `to_world`.
// A moving sphere is drawn where it is at `time`, the time of the tree's rays.
void draw_shape(const Shape& shape, const Affine& to_world, const PageProjection& proj, double unit, Real time,
                std::string& out) {
    const std::string fill_style =
        "fill=\"#d9dde3\" fill-opacity=\"0.55\" stroke=\"#6b7280\" stroke-width=\"" + num(unit) + "\"";
    const char* kFill = fill_style.c_str();
    constexpr std::size_t kMaxTriangles = 3000;  // past this, a mesh is drawn as the hull of its vertices
    // The silhouette of a (transformed) convex solid: the hull of points on it.
    const auto hull_of = [&](const std::vector<Vec3>& points) {
        std::vector<P2> pts;
        for (const Vec3& p : points) pts.push_back(proj(to_world.point(p)));
        out += polygon(hull(pts), kFill);
    };
    match(
        shape,
        [&](const Sphere& moving) {
            const Sphere s = moving.at(time);
            std::vector<Vec3> points;
            for (int i = 0; i <= 16; ++i)
                for (int j = 0; j < 32; ++j) {
                    const double th = M_PI * i / 16, ph = 2 * M_PI * j / 32;
                    const Vec3 d(Real(std::sin(th) * std::cos(ph)), Real(std::cos(th)),
                                 Real(std::sin(th) * std::sin(ph)));
                    points.push_back(s.center + s.radius * d);
                }
            hull_of(points);
        },
        [&](const Triangle& t) {
            out += polygon({proj(to_world.point(t.a)), proj(to_world.point(t.b)), proj(to_world.point(t.c))}, kFill);
        },
        [&](const Polygon& p) {
            std::vector<P2> pts;
            for (const Vec3& v : p.vertices()) pts.push_back(proj(to_world.point(v)));
            out += polygon(pts, kFill);
        },
        [&](const Mesh& m) {
            const MeshData& d = m.data();
            if (d.triangles.size() > kMaxTriangles) {
                std::vector<Vec3> points(d.positions.begin(), d.positions.end());
                hull_of(points);
                return;
            }
            out += "<path fill=\"#d9dde3\" fill-opacity=\"0.25\" stroke=\"#9ca3af\" stroke-width=\"" + num(0.5 * unit) +
                   "\" d=\"";
            for (const auto& tri : d.triangles) {
                const P2 a = proj(to_world.point(d.positions[tri[0]])), b = proj(to_world.point(d.positions[tri[1]])),
                         c = proj(to_world.point(d.positions[tri[2]]));
                out += "M" + num(a.x) + "," + num(a.y) + "L" + num(b.x) + "," + num(b.y) + "L" + num(c.x) + "," +
                       num(c.y) + "Z";
            }
            out += "\"/>\n";
        },
        [&](const Instance& in) { draw_shape(in.base(), in.to_world().then(to_world), proj, unit, time, out); },
        [&](const Cuboid& box) {
            std::vector<Vec3> corners;
            for (int k = 0; k < 8; ++k)
                corners.push_back(
                    Vec3(k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z));
            hull_of(corners);
        },
        [&](const Csg& csg) {  // both operands, as outlines
            draw_shape(*csg.left().shape, to_world, proj, unit, time, out);
            draw_shape(*csg.right().shape, to_world, proj, unit, time, out);
        });
}

const char* kind_color(RayKind k) {
    switch (k) {
        case RayKind::camera:
            return "#111827";
        case RayKind::shadow:
            return "#d97706";
        case RayKind::reflection:
            return "#2563eb";
        case RayKind::refraction:
            break;
    }
    return "#059669";
}

}  // namespace

std::string ray_tree_svg(const Scene& scene, const RayTree& tree, const std::string& title, const Color& pixel) {
    const View view = scene.camera.view(2, 2);
    const Vec3 eye = scene.camera.eye;
    const Vec3 forward = -view.uvw.w;
    // Where each ray ends: its hit, or (for a ray that escapes) a little past the frame.
    std::vector<Vec3> points{eye};
    for (const RayNode& n : tree.nodes) {
        points.push_back(n.ray.origin);
        if (n.hit) points.push_back(n.record.p);
    }
    // From above (across = the camera's right) or from the side (across = its up):
    // whichever spreads the tree's points more.
    double spread_u = 0, spread_v = 0;
    for (const Vec3& p : points) {
        spread_u = std::max(spread_u, std::abs(double(glm::dot(p - eye, view.uvw.u))));
        spread_v = std::max(spread_v, std::abs(double(glm::dot(p - eye, view.uvw.v))));
    }
    const bool from_above = spread_u >= spread_v;
    const PageProjection proj{eye, from_above ? view.uvw.u : view.uvw.v, forward};

    P2 lo{1e300, 1e300}, hi{-1e300, -1e300};
    for (const Vec3& p : points) {
        const P2 q = proj(p);
        lo = {std::min(lo.x, q.x), std::min(lo.y, q.y)};
        hi = {std::max(hi.x, q.x), std::max(hi.y, q.y)};
    }
    const double size = std::max({hi.x - lo.x, hi.y - lo.y, 1e-6});
    const double pad = 0.25 * size;
    lo = {lo.x - pad, lo.y - pad};
    hi = {hi.x + pad, hi.y + pad};
    // No narrower than 4:5, so that the header fits.
    if (const double short_by = 0.8 * (hi.y - lo.y) - (hi.x - lo.x); short_by > 0) {
        lo.x -= short_by / 2;
        hi.x += short_by / 2;
    }
    const double w = hi.x - lo.x, h = hi.y - lo.y;
    const double unit = std::max(w, h) / 600;  // one pixel of a 600-pixel picture, in scene units
    const auto escape_end = [&](const Ray& r) {
        return r.origin + Real(0.6 * std::max(w, h)) * unit_vector(r.direction);
    };

    std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" + num(lo.x) + " " + num(lo.y - 0.12 * h) +
                      " " + num(w) + " " + num(h * 1.12) + "\" width=\"" + num(600 * w / std::max(w, h)) +
                      "\" height=\"" + num(600 * h * 1.12 / std::max(w, h)) + "\" font-family=\"sans-serif\">\n";
    out += "<title>" + xml_escape(title) + "</title>\n";
    out += "<rect x=\"" + num(lo.x) + "\" y=\"" + num(lo.y - 0.12 * h) + "\" width=\"" + num(w) + "\" height=\"" +
           num(h * 1.12) + "\" fill=\"#ffffff\"/>\n";
    // Header: what this is, and the pixel's colour.
    const double fs = 11 * unit;
    out += "<text x=\"" + num(lo.x + 6 * unit) + "\" y=\"" + num(lo.y - 0.12 * h + 14 * unit) + "\" font-size=\"" +
           num(fs) + "\">" + xml_escape(title) + " — seen " + (from_above ? "from above" : "from the side") +
           ", the eye at the bottom</text>\n";
    out += "<rect x=\"" + num(hi.x - 40 * unit) + "\" y=\"" + num(lo.y - 0.12 * h + 4 * unit) + "\" width=\"" +
           num(34 * unit) + "\" height=\"" + num(14 * unit) + "\" fill=\"" + rgb(pixel) +
           "\" stroke=\"#000\" stroke-width=\"" + num(unit) + "\"><title>pixel colour " + triple(pixel) +
           "</title></rect>\n";
    double lx = lo.x + 6 * unit;
    for (std::size_t k = 0; k < kRayKinds; ++k) {
        out += "<text x=\"" + num(lx) + "\" y=\"" + num(lo.y - 0.12 * h + 30 * unit) + "\" font-size=\"" + num(fs) +
               "\" fill=\"" + kind_color(RayKind(k)) + "\">— " + kRayKindNames[RayKind(k)] + "</text>\n";
        lx += 80 * unit;
    }

    const Real time = tree.nodes.empty() ? 0 : tree.nodes.front().ray.time;
    for (const Surface& s : scene.surfaces.surfaces()) draw_shape(s.shape, Affine{}, proj, unit, time, out);
    // Point lights as suns, parallelogram lights as their outline. Directional lights have no
    // place to be drawn: their shadow rays leave the picture towards them.
    for (std::size_t k = 0; k < scene.lights.size(); ++k) {
        const Light& l = scene.lights[k];
        if (l.type == Light::Type::point) {
            const P2 q = proj(l.position);
            out += "<circle cx=\"" + num(q.x) + "\" cy=\"" + num(q.y) + "\" r=\"" + num(7 * unit) +
                   "\" fill=\"#fde047\" stroke=\"#a16207\" stroke-width=\"" + num(unit) + "\"><title>light " +
                   std::to_string(k) + ", colour " + triple(l.color) + "</title></circle>\n";
        } else if (l.is_area()) {
            const std::vector<P2> corners = {proj(l.position), proj(l.position + l.edge_a),
                                             proj(l.position + l.edge_a + l.edge_b), proj(l.position + l.edge_b)};
            const std::string style =
                "fill=\"#fde047\" fill-opacity=\"0.6\" stroke=\"#a16207\" stroke-width=\"" + num(unit) + "\"";
            out += polygon(corners, style.c_str());
        }
    }
    // How much of each ray reaches the pixel: the product of the weights on the way there.
    // Rays that matter little fade, and only rays that matter are labelled.
    std::vector<double> reach(tree.nodes.size(), 1.0);
    for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
        const RayNode& n = tree.nodes[i];
        const double own = n.kind == RayKind::shadow ? 1.0 : (n.weight.r + n.weight.g + n.weight.b) / 3.0;
        reach[i] = (n.parent >= 0 ? reach[std::size_t(n.parent)] : 1.0) * own;
    }
    // The rays, parents first so that children draw on top.
    for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
        const RayNode& n = tree.nodes[i];
        const double opacity = 0.15 + 0.85 * std::sqrt(std::clamp(reach[i], 0.0, 1.0));
        const bool label = reach[i] >= 0.05;
        const Vec3 end = n.hit                                                                ? n.record.p
                         : n.kind == RayKind::shadow && std::isfinite(double(n.interval.max)) ? n.ray.at(n.interval.max)
                                                                                              : escape_end(n.ray);
        const P2 a = proj(n.ray.origin), b = proj(end);
        const bool blocked_shadow = n.kind == RayKind::shadow && n.hit;
        const double width = (n.kind == RayKind::camera ? 2.2 : 1.6) * unit;
        std::string tip = std::string(kRayKindNames[n.kind]) + " ray, depth " + std::to_string(n.depth);
        if (n.kind == RayKind::shadow)
            tip += ", to light " + std::to_string(n.light) + (n.hit ? ": BLOCKED" : ": reaches the light");
        else if (n.hit) {
            tip += ", hits " + scene.surfaces.name(n.record.surface) + " at t = " + num(double(n.record.t));
            if (n.record.part != kNone)  // which operand of a CSG object
                tip += " (" + describe_part(scene.surfaces[n.record.surface].shape, n.record.part) + ")";
        } else
            tip += ", hits nothing: background";
        if (*n.weight_of) {
            tip += "\nweight (";
            tip += n.weight_of;
            tip += "): " + triple(n.weight);
        }
        tip += "\nbrings back " + triple(n.radiance);
        tip += "\nshare of the pixel it carries: " + num(reach[i]);
        if (*n.note) {
            tip += '\n';
            tip += n.note;
        }
        out += "<line x1=\"" + num(a.x) + "\" y1=\"" + num(a.y) + "\" x2=\"" + num(b.x) + "\" y2=\"" + num(b.y) +
               "\" stroke=\"" + (blocked_shadow ? std::string("#dc2626") : kind_color(n.kind)) + "\" stroke-width=\"" +
               num(width) + "\"" +
               (n.kind == RayKind::shadow ? " stroke-dasharray=\"" + num(5 * unit) + "," + num(3 * unit) + "\"" : "") +
               " stroke-opacity=\"" + num(opacity) + "\"><title>" + xml_escape(tip) + "</title></line>\n";
        if (n.hit) {
            const char* fill = blocked_shadow ? "#dc2626" : "#111827";
            out += "<circle cx=\"" + num(b.x) + "\" cy=\"" + num(b.y) + "\" r=\"" + num(3 * unit) + "\" fill=\"" +
                   fill + "\"><title>" + xml_escape(tip) + "</title></circle>\n";
        }
        // Label the weight where it is not 1: how much of this ray reaches its parent.
        if (label && *n.weight_of && n.kind != RayKind::shadow) {
            const double mx = (a.x + b.x) / 2, my = (a.y + b.y) / 2;
            const float g = (n.weight.r + n.weight.g + n.weight.b) / 3;
            out += "<text x=\"" + num(mx + 4 * unit) + "\" y=\"" + num(my) + "\" font-size=\"" + num(9 * unit) +
                   "\" fill=\"" + kind_color(n.kind) + "\">×" + num(g) + " " + xml_escape(n.weight_of) + "</text>\n";
        }
        if (blocked_shadow && label)
            out += "<text x=\"" + num(b.x + 4 * unit) + "\" y=\"" + num(b.y - 4 * unit) + "\" font-size=\"" +
                   num(9 * unit) + "\" fill=\"#dc2626\">blocked</text>\n";
    }
    const P2 e = proj(eye);
    out += "<circle cx=\"" + num(e.x) + "\" cy=\"" + num(e.y) + "\" r=\"" + num(5 * unit) +
           "\" fill=\"#111827\"><title>the eye</title></circle>\n";
    out += "</svg>\n";
    return out;
}

}  // namespace rt
