// Chapter 04: polygons, convex and concave, facing along every axis.
#include "common/app.hpp"
#include "common/integrators.hpp"
#include "common/polygon.hpp"
#include "common/surface_list.hpp"

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

static Scene scene_of(std::shared_ptr<SurfaceList> world, Vec3 eye) {
    Scene s;
    s.camera.eye = eye;
    s.camera.target = Vec3(0);
    s.camera.vertical_fov_degrees = 45;
    s.world = std::move(world);
    s.background = Color(0.1f, 0.1f, 0.12f);
    s.integrator = std::make_shared<NormalIntegrator>();
    return s;
}

int main(int argc, char** argv) {
    ChapterApp app("ch04", "Polygons");
    const Vec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
    app.add_scene("convex", "a hexagon, a pentagon and a square, tilted", [=] {
        auto w = std::make_shared<SurfaceList>();
        w->add(std::make_shared<Polygon>("hexagon", star(Vec3(-1.3, 0, 0), X, glm::normalize(Y + Z * Real(0.3)), 6, 0.8, 0.8)));
        w->add(std::make_shared<Polygon>("pentagon", star(Vec3(0.6, 0.6, 0), glm::normalize(X + Z * Real(0.4)), Y, 5, 0.6, 0.6)));
        w->add(std::make_shared<Polygon>("square", star(Vec3(0.6, -0.8, 0), X, Y, 4, 0.5, 0.5)));
        return scene_of(w, Vec3(0, 0, 5));
    });
    app.add_scene("concave", "a five-pointed star and an L shape: concave polygons", [=] {
        auto w = std::make_shared<SurfaceList>();
        w->add(std::make_shared<Polygon>("star", star(Vec3(-0.9, 0, 0), X, Y, 5, 1, 0.4)));
        w->add(std::make_shared<Polygon>("L", std::vector<Vec3>{{0.4, -1, 0}, {1.6, -1, 0}, {1.6, -0.6, 0},
                                                               {0.8, -0.6, 0}, {0.8, 1, 0}, {0.4, 1, 0}}));
        return scene_of(w, Vec3(0.3, 0.4, 5));
    });
    app.add_scene("axes", "three squares facing along x, y and z: each projects onto a different plane", [=] {
        auto w = std::make_shared<SurfaceList>();
        w->add(std::make_shared<Polygon>("facing x", star(Vec3(-0.9, 0, 0), Y, Z, 4, 0.7, 0.7)));
        w->add(std::make_shared<Polygon>("facing y", star(Vec3(0, -0.9, 0), Z, X, 4, 0.7, 0.7)));
        w->add(std::make_shared<Polygon>("facing z", star(Vec3(0, 0, -0.9), X, Y, 4, 0.7, 0.7)));
        return scene_of(w, Vec3(3, 2.5, 3.5));
    });
    return app.run(argc, argv);
}
