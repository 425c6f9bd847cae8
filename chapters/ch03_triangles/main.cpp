// Chapter 03: triangles and triangle meshes, coloured by barycentric coordinates or normals.
#include "common/app.hpp"
#include "common/integrators.hpp"
#include "common/procedural.hpp"
#include "common/surface_list.hpp"
#include "common/triangle.hpp"

#include <memory>

using namespace rt;

static Scene view_of(std::shared_ptr<const Surface> world, Vec3 eye, Vec3 target, Real fov,
                     std::shared_ptr<const Integrator> integrator) {
    Scene s;
    s.camera.eye = eye;
    s.camera.target = target;
    s.camera.vertical_fov_degrees = fov;
    s.world = std::move(world);
    s.background = Color(0.1f, 0.1f, 0.12f);
    s.integrator = std::move(integrator);
    return s;
}

int main(int argc, char** argv) {
    ChapterApp app("ch03", "Triangles");
    app.add_scene("triangle", "the course's exercise-2 triangle, coloured by (1 - beta - gamma, beta, gamma)", [] {
        auto t = std::make_shared<Triangle>("triangle", Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1));
        return view_of(t, Vec3(2, 2, 2), Vec3(Real(1) / 3), 40, std::make_shared<BarycentricIntegrator>());
    });
    app.add_scene("icosphere", "an icosahedron subdivided three times: 1280 triangles, shaded by normal", [] {
        auto m = std::make_shared<TriangleMesh>("icosphere", icosphere(Vec3(0), 1, 3));
        return view_of(m, Vec3(0.5, 1, 3.2), Vec3(0), 45, std::make_shared<NormalIntegrator>());
    });
    app.add_scene("cube", "a cube, each face cut into 4 x 4 squares: barycentric colours show every triangle", [] {
        auto m = std::make_shared<TriangleMesh>("cube", subdivided_cube(Vec3(0), 1.5, 4));
        return view_of(m, Vec3(2.2, 1.8, 2.6), Vec3(0), 45, std::make_shared<BarycentricIntegrator>());
    });
    app.add_scene("terrain", "a height field of 2 x 32 x 32 triangles, shaded by normal", [] {
        auto m = std::make_shared<TriangleMesh>("terrain", terrain(Vec3(0), 4, 0.6, 32));
        return view_of(m, Vec3(0, 2.2, 3.2), Vec3(0, -0.2, 0), 45, std::make_shared<NormalIntegrator>());
    });
    app.add_scene("soup", "400 unconnected random triangles", [] {
        auto m = std::make_shared<TriangleMesh>("soup", triangle_soup(Vec3(0), 2, 0.4, 400, 7));
        return view_of(m, Vec3(0, 0, 3.5), Vec3(0), 45, std::make_shared<NormalIntegrator>());
    });
    return app.run(argc, argv);
}
