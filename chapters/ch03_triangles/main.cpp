// Chapter 03: triangles and triangle meshes, coloured by barycentric coordinates or normals.
#include "app/app.hpp"
#include "geometry/procedural.hpp"
#include "geometry/triangle.hpp"
#include "render/integrators.hpp"

#include <memory>

using namespace rt;

static Scene view_of(Shape shape, const char* name, Vec3 eye, Vec3 target, Real fov,
                     std::shared_ptr<const Integrator> integrator) {
    Scene s = look_at(eye, target, fov, std::move(integrator));
    s.surfaces.add(std::move(shape), 0, name);
    return s;
}

int main(int argc, char** argv) {
    ChapterApp app("ch03", "Triangles");
    app.add_scene("triangle", "the course's exercise-2 triangle, coloured by (1 - beta - gamma, beta, gamma)", [] {
        return view_of(Triangle(Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)), "triangle", Vec3(2, 2, 2),
                       Vec3(Real(1) / 3), 40, std::make_shared<BarycentricIntegrator>());
    });
    app.add_scene("icosphere", "an icosahedron subdivided three times: 1280 triangles, shaded by normal", [] {
        return view_of(Mesh(icosphere(Vec3(0), 1, 3)), "icosphere", Vec3(0.5, 1, 3.2), Vec3(0), 45,
                       std::make_shared<NormalIntegrator>());
    });
    app.add_scene("cube", "a cube, each face cut into 4 x 4 squares: barycentric colours show every triangle", [] {
        return view_of(Mesh(subdivided_cube(Vec3(0), 1.5, 4)), "cube", Vec3(2.2, 1.8, 2.6), Vec3(0), 45,
                       std::make_shared<BarycentricIntegrator>());
    });
    app.add_scene("terrain", "a height field of 2 x 32 x 32 triangles, shaded by normal", [] {
        return view_of(Mesh(terrain(Vec3(0), 4, 0.6, 32)), "terrain", Vec3(0, 2.2, 3.2), Vec3(0, -0.2, 0), 45,
                       std::make_shared<NormalIntegrator>());
    });
    app.add_scene("soup", "400 unconnected random triangles", [] {
        return view_of(Mesh(triangle_soup(Vec3(0), 2, 0.4, 400, 7)), "soup", Vec3(0, 0, 3.5), Vec3(0), 45,
                       std::make_shared<NormalIntegrator>());
    });
    return app.run(argc, argv);
}
