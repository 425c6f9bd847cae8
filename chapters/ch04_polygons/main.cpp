// Chapter 04: polygons, convex and concave, facing along every axis.
#include "app/app.hpp"
#include "geometry/polygon.hpp"
#include "render/integrators.hpp"

#include <cmath>
#include <memory>

using namespace rt;

// A regular n-gon (or, with inner < outer, an n-pointed star) in the plane through c
// spanned by unit vectors a and b.
static std::vector<Vec3> star(Vec3 c, Vec3 a, Vec3 b, int n, Real outer, Real inner) {
    std::vector<Vec3> v;
    const int corners = inner == outer ? n : 2 * n;
    for (int k = 0; k < corners; ++k) {
        const Real angle = Real(2 * M_PI) * Real(k) / Real(corners) + Real(M_PI / 2);
        const Real r = (inner == outer || k % 2 == 0) ? outer : inner;
        v.push_back(c + r * (std::cos(angle) * a + std::sin(angle) * b));
    }
    return v;
}

static Scene polygons(Vec3 eye, std::initializer_list<std::pair<const char*, std::vector<Vec3>>> named) {
    Scene s = look_at(eye, Vec3(0), 45, std::make_shared<NormalIntegrator>());
    for (const auto& [name, vertices] : named) s.surfaces.add(Polygon(vertices), 0, name);
    return s;
}

int main(int argc, char** argv) {
    ChapterApp app("ch04", "Polygons");
    const Vec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
    app.add_scene("convex", "a hexagon, a pentagon and a square, tilted", [=] {
        return polygons(Vec3(0, 0, 5),
                        {{"hexagon", star(Vec3(-1.3, 0, 0), X, glm::normalize(Y + Z * Real(0.3)), 6, 0.8, 0.8)},
                         {"pentagon", star(Vec3(0.6, 0.6, 0), glm::normalize(X + Z * Real(0.4)), Y, 5, 0.6, 0.6)},
                         {"square", star(Vec3(0.6, -0.8, 0), X, Y, 4, 0.5, 0.5)}});
    });
    app.add_scene("concave", "a five-pointed star and an L shape: concave polygons", [=] {
        return polygons(
            Vec3(0.3, 0.4, 5),
            {{"star", star(Vec3(-0.9, 0, 0), X, Y, 5, 1, 0.4)},
             {"L", {{0.4, -1, 0}, {1.6, -1, 0}, {1.6, -0.6, 0}, {0.8, -0.6, 0}, {0.8, 1, 0}, {0.4, 1, 0}}}});
    });
    app.add_scene("axes", "three squares facing along x, y and z: each projects onto a different plane", [=] {
        return polygons(Vec3(3, 2.5, 3.5), {{"facing x", star(Vec3(-0.9, 0, 0), Y, Z, 4, 0.7, 0.7)},
                                            {"facing y", star(Vec3(0, -0.9, 0), Z, X, 4, 0.7, 0.7)},
                                            {"facing z", star(Vec3(0, 0, -0.9), X, Y, 4, 0.7, 0.7)}});
    });
    return app.run(argc, argv);
}
