#include "svg.hpp"

#include "core/xml.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace figures {

namespace {

// The one palette. Strong colours for what moves (rays, normals), grey for what stands.
struct Colors {
    const char* stroke;
    const char* fill;
};
Colors palette(Ink ink) {
    switch (ink) {
        case Ink::camera:
            return {"#1d4ed8", "#dbeafe"};
        case Ink::shadow:
            return {"#c26d00", "#fef3c7"};
        case Ink::reflected:
            return {"#047857", "#d1fae5"};
        case Ink::refracted:
            return {"#7c3aed", "#ede9fe"};
        case Ink::normal:
            return {"#a11d1d", "#fee2e2"};
        case Ink::surface:
            return {"#6b7280", "#e5e7eb"};
        case Ink::hit:
            return {"#111111", "#111111"};
        case Ink::axis:
            return {"#1f2937", "#f3f4f6"};
        case Ink::guide:
            return {"#9ca3af", "#f9fafb"};
        case Ink::light:
        default:
            return {"#a16207", "#fde047"};
    }
}

// Text in the stroke's colour, except where that is too pale to read in print.
const char* text_color(Ink ink) {
    return palette(ink == Ink::guide ? Ink::surface : ink).stroke;
}

constexpr double kWidth = 640;      // page width, pixels
constexpr double kMaxHeight = 560;  // a tall figure is narrowed rather than made taller than this
constexpr double kMargin = 14;      // white space around everything, pixels
constexpr double kFont = 17, kSmallFont = 15;
constexpr double kStroke = 2.2;

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", v);
    return buf;
}

// Characters, not bytes: a Greek letter or a subscript is one glyph of two or three bytes.
std::size_t glyphs(const std::string& s) {
    return std::size_t(
        std::count_if(s.begin(), s.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

// World to page: x right, y down, pixels.
struct Page {
    P2 lo{0, 0};
    double top = 0, scale = 1, x0 = 0, y0 = 0;
    P2 operator()(P2 p) const { return {x0 + (p.x - lo.x) * scale, y0 + (top - p.y) * scale}; }
};

std::string stroke_attrs(Ink ink, Stroke stroke) {
    std::string s = " stroke=\"" + std::string(palette(ink).stroke) + "\" stroke-width=\"" +
                    num(stroke == Stroke::thin ? 1.3 : kStroke) + "\"";
    if (stroke == Stroke::dashed) s += " stroke-dasharray=\"7,5\"";
    return s;
}

std::string points_attr(const std::vector<P2>& pts, const Page& page) {
    std::string s;
    for (P2 p : pts) {
        const P2 q = page(p);
        s += num(q.x) + "," + num(q.y) + " ";
    }
    return s;
}

}  // namespace

Canvas::Item& Canvas::add(Type type, std::vector<P2> points, Ink ink, Stroke stroke) {
    Item& it = items_.emplace_back();
    it.type = type;
    it.points = std::move(points);
    it.ink = ink;
    it.stroke = stroke;
    return it;
}

void Canvas::line(P2 a, P2 b, Ink ink, Stroke stroke) {
    add(Type::line, {a, b}, ink, stroke);
}
void Canvas::arrow(P2 from, P2 to, Ink ink, Stroke stroke) {
    add(Type::arrow, {from, to}, ink, stroke);
}
void Canvas::polyline(const std::vector<P2>& points, Ink ink, Stroke stroke) {
    add(Type::polyline, points, ink, stroke);
}
void Canvas::polygon(const std::vector<P2>& points, Ink ink, bool fill, Stroke stroke) {
    add(Type::polygon, points, ink, stroke).fill = fill;
}
void Canvas::circle(P2 center, double radius, Ink ink, bool fill, Stroke stroke) {
    Item& it = add(Type::circle, {center, center - P2{radius, radius}, center + P2{radius, radius}}, ink, stroke);
    it.fill = fill;
    it.size = radius;
}
void Canvas::dot(P2 p, Ink ink, bool hollow) {
    add(Type::dot, {p}, ink).fill = !hollow;
}
void Canvas::angle(P2 center, P2 from, P2 to, double radius_px, Ink ink) {
    add(Type::angle, {center, from, to}, ink, Stroke::thin).size = radius_px;
}
void Canvas::label(P2 at, const std::string& text, Ink ink, double dx, double dy, Anchor anchor, bool small) {
    Item& it = add(Type::label, {at}, ink);
    it.text = text;
    it.dx = dx;
    it.dy = dy;
    it.anchor = anchor;
    it.fill = small;
}

std::string Canvas::svg(const std::string& title) const {
    // The drawing's extent in the world (labels by their anchor only) ...
    P2 lo{1e300, 1e300}, hi{-1e300, -1e300};
    for (const Item& it : items_) {
        const std::size_t n = it.type == Type::angle || it.type == Type::label ? 1 : it.points.size();
        for (std::size_t k = 0; k < n; ++k) {
            lo = {std::min(lo.x, it.points[k].x), std::min(lo.y, it.points[k].y)};
            hi = {std::max(hi.x, it.points[k].x), std::max(hi.y, it.points[k].y)};
        }
    }
    if (items_.empty()) lo = hi = {0, 0};
    const double w = std::max(hi.x - lo.x, 1e-9), h = std::max(hi.y - lo.y, 1e-9);
    // ... and how far the labels and dots reach past it on the page, at the scale that would
    // frame it; the scale is then shrunk until both fit, a few rounds being enough.
    double scale = std::min((kWidth - 2 * kMargin) / w, (kMaxHeight - 2 * kMargin) / h);
    Page page;
    double left = 0, right = 0, up = 0, down = 0;  // past the world's extent, pixels
    for (int round = 0; round < 4; ++round) {
        page = Page{lo, hi.y, scale, 0, 0};
        left = right = up = down = 8;  // a dot's radius, an arrow's head
        for (const Item& it : items_) {
            if (it.type != Type::label) continue;
            const double font = it.fill ? kSmallFont : kFont;
            const double tw = 0.56 * font * double(glyphs(it.text));
            const P2 q = page(it.points[0]) + P2{it.dx, -it.dy};
            const double x1 = it.anchor == Anchor::start ? q.x : it.anchor == Anchor::middle ? q.x - tw / 2 : q.x - tw;
            left = std::max(left, -x1);
            right = std::max(right, x1 + tw - w * scale);
            up = std::max(up, -(q.y - font * 0.8));
            down = std::max(down, q.y + font * 0.3 - h * scale);
        }
        const double fit =
            std::min((kWidth - 2 * kMargin - left - right) / w, (kMaxHeight - 2 * kMargin - up - down) / h);
        if (fit >= scale * 0.999) break;
        scale = fit;
    }
    const double page_w = kWidth, page_h = h * scale + up + down + 2 * kMargin;
    // Centred across the page.
    const double x0 = kMargin + left + (kWidth - 2 * kMargin - left - right - w * scale) / 2;
    page = Page{lo, hi.y, scale, x0, kMargin + up};

    std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " + num(page_w) + " " + num(page_h) +
                      "\" width=\"" + num(page_w) + "\" height=\"" + num(page_h) +
                      "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n";
    out += "<title>" + rt::xml_escape(title) + "</title>\n";
    out += "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
    for (const Item& it : items_) {
        const Colors c = palette(it.ink);
        switch (it.type) {
            case Type::line: {
                const P2 a = page(it.points[0]), b = page(it.points[1]);
                out += "<line x1=\"" + num(a.x) + "\" y1=\"" + num(a.y) + "\" x2=\"" + num(b.x) + "\" y2=\"" +
                       num(b.y) + "\"" + stroke_attrs(it.ink, it.stroke) + " stroke-linecap=\"round\"/>\n";
                break;
            }
            case Type::arrow: {
                const P2 a = page(it.points[0]), b = page(it.points[1]);
                const double len = std::hypot(b.x - a.x, b.y - a.y);
                if (len < 1e-9) break;
                const P2 u = (1 / len) * (b - a), n{-u.y, u.x};
                const double head = std::min(13.0, 0.45 * len), half = 0.4 * head;
                const P2 base = b - head * u;
                out += "<line x1=\"" + num(a.x) + "\" y1=\"" + num(a.y) + "\" x2=\"" + num(base.x) + "\" y2=\"" +
                       num(base.y) + "\"" + stroke_attrs(it.ink, it.stroke) + "/>\n";
                out += "<polygon points=\"" + num(b.x) + "," + num(b.y) + " " + num(base.x + half * n.x) + "," +
                       num(base.y + half * n.y) + " " + num(base.x - half * n.x) + "," + num(base.y - half * n.y) +
                       "\" fill=\"" + c.stroke + "\"/>\n";
                break;
            }
            case Type::polyline:
                out += "<polyline points=\"" + points_attr(it.points, page) + "\" fill=\"none\"" +
                       stroke_attrs(it.ink, it.stroke) + " stroke-linejoin=\"round\"/>\n";
                break;
            case Type::polygon:
                out += "<polygon points=\"" + points_attr(it.points, page) + "\" fill=\"" +
                       (it.fill ? c.fill : "none") + "\"" + stroke_attrs(it.ink, it.stroke) +
                       " stroke-linejoin=\"round\"/>\n";
                break;
            case Type::circle: {
                const P2 q = page(it.points[0]);
                out += "<circle cx=\"" + num(q.x) + "\" cy=\"" + num(q.y) + "\" r=\"" + num(it.size * scale) +
                       "\" fill=\"" + (it.fill ? c.fill : "none") + "\"" + stroke_attrs(it.ink, it.stroke) + "/>\n";
                break;
            }
            case Type::dot: {
                const P2 q = page(it.points[0]);
                out += "<circle cx=\"" + num(q.x) + "\" cy=\"" + num(q.y) + "\" r=\"4.5\" fill=\"" +
                       (it.fill ? c.stroke : "#ffffff") + "\" stroke=\"" + c.stroke + "\" stroke-width=\"1.8\"/>\n";
                break;
            }
            case Type::angle: {
                // Directions on the page (y down), and the shorter way round between them.
                const P2 q = page(it.points[0]);
                double a0 = std::atan2(-it.points[1].y, it.points[1].x),
                       a1 = std::atan2(-it.points[2].y, it.points[2].x);
                double sweep = a1 - a0;
                while (sweep > M_PI) sweep -= 2 * M_PI;
                while (sweep < -M_PI) sweep += 2 * M_PI;
                const double r = it.size;
                const P2 s{q.x + r * std::cos(a0), q.y + r * std::sin(a0)};
                const P2 e{q.x + r * std::cos(a0 + sweep), q.y + r * std::sin(a0 + sweep)};
                out += "<path d=\"M" + num(s.x) + "," + num(s.y) + " A" + num(r) + "," + num(r) + " 0 0 " +
                       (sweep > 0 ? "1 " : "0 ") + num(e.x) + "," + num(e.y) + "\" fill=\"none\"" +
                       stroke_attrs(it.ink, Stroke::thin) + "/>\n";
                break;
            }
            case Type::label: {
                const P2 q = page(it.points[0]) + P2{it.dx, -it.dy};
                const char* anchor = it.anchor == Anchor::start    ? "start"
                                     : it.anchor == Anchor::middle ? "middle"
                                                                   : "end";
                // A white halo keeps a label readable where it crosses a line.
                out += "<text x=\"" + num(q.x) + "\" y=\"" + num(q.y) + "\" font-size=\"" +
                       num(it.fill ? kSmallFont : kFont) + "\" text-anchor=\"" + anchor + "\" fill=\"" +
                       text_color(it.ink) + "\" stroke=\"#ffffff\" stroke-width=\"4\" paint-order=\"stroke\">" +
                       rt::xml_escape(it.text) + "</text>\n";
                break;
            }
        }
    }
    out += "</svg>\n";
    return out;
}

}  // namespace figures
