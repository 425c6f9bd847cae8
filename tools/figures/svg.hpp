#pragma once
// The book's diagrams as SVG: a small canvas in world coordinates (y up), laid out on a page
// 640 pixels wide when written. A figure draws in the units of its own geometry and never
// chooses a view box: the canvas frames whatever was drawn, with a margin for the labels.
// The palette is here and nowhere else, so that a shadow ray has one colour in every figure.
#include "core/real.hpp"

#include <string>
#include <vector>

namespace figures {

struct P2 {
    double x, y;
};
inline P2 operator+(P2 a, P2 b) {
    return {a.x + b.x, a.y + b.y};
}
inline P2 operator-(P2 a, P2 b) {
    return {a.x - b.x, a.y - b.y};
}
inline P2 operator*(double s, P2 a) {
    return {s * a.x, s * a.y};
}
// A point of the plane z = 0, where the flat figures draw the library's 3D objects.
inline P2 flat(const rt::Vec3& p) {
    return {double(p.x), double(p.y)};
}

// What a stroke stands for; its colour is the palette's (svg.cpp).
enum class Ink {
    camera,     // camera (primary) rays: blue
    shadow,     // shadow rays: amber
    reflected,  // reflected rays: green
    refracted,  // refracted rays: purple
    normal,     // normals: dark red
    surface,    // surfaces and boxes: grey, lightly filled
    hit,        // hit points: black
    axis,       // frames and the image window: near black
    guide,      // construction lines, closest approaches: light grey
    light,      // lights: yellow
};

enum class Stroke { solid, dashed, thin };
enum class Anchor { start, middle, end };

class Canvas {
public:
    void line(P2 a, P2 b, Ink ink, Stroke stroke = Stroke::solid);
    // An arrow from `from` to `to`, the head drawn at the page's scale.
    void arrow(P2 from, P2 to, Ink ink, Stroke stroke = Stroke::solid);
    void polyline(const std::vector<P2>& points, Ink ink, Stroke stroke = Stroke::solid);
    // A closed outline; `fill` shades it in its ink's light fill.
    void polygon(const std::vector<P2>& points, Ink ink, bool fill = true, Stroke stroke = Stroke::solid);
    void circle(P2 center, double radius, Ink ink, bool fill = true, Stroke stroke = Stroke::solid);
    void box(P2 lo, P2 hi, Ink ink, bool fill = true) { polygon({lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}, ink, fill); }
    // A dot of a fixed size on the page: a hit point, an eye, a sample.
    void dot(P2 p, Ink ink, bool hollow = false);
    // The angle at `center` from direction `from` to direction `to` (the shorter way), drawn
    // `radius_px` pixels out.
    void angle(P2 center, P2 from, P2 to, double radius_px, Ink ink);
    // A label at `at`, moved by (dx, dy) page pixels (dy up, like the world's y).
    void label(P2 at, const std::string& text, Ink ink = Ink::axis, double dx = 6, double dy = 6,
               Anchor anchor = Anchor::start, bool small = false);

    // The picture: every item drawn, framed with a margin, on a white page 640 pixels wide.
    // `title` becomes the SVG's <title> (what a screen reader says).
    std::string svg(const std::string& title) const;

private:
    enum class Type { line, arrow, polyline, polygon, circle, dot, angle, label };
    struct Item {
        Type type = Type::line;
        std::vector<P2> points;
        Ink ink = Ink::axis;
        Stroke stroke = Stroke::solid;
        bool fill = false;
        double size = 0;  // circle: radius in world units; angle: radius in pixels
        double dx = 0, dy = 0;
        Anchor anchor = Anchor::start;
        std::string text;
    };
    Item& add(Type type, std::vector<P2> points, Ink ink, Stroke stroke = Stroke::solid);
    std::vector<Item> items_;
};

}  // namespace figures
