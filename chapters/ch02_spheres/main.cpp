// Chapter 02: spheres, shaded by their unit normals.
#include "app/app.hpp"
#include "geometry/sphere.hpp"
#include "render/integrators.hpp"

#include <memory>

using namespace rt;

static Scene sphere_scene(Projection projection, Vec3 eye, Vec3 center, Real radius, Real vfov_degrees) {
    Scene s = look_at(eye, center, vfov_degrees, std::make_shared<NormalIntegrator>());
    s.camera.projection = projection;
    s.camera.window_height = 3 * radius;
    s.surfaces.add(Sphere(center, radius), 0, "sphere");
    return s;
}

int main(int argc, char** argv) {
    ChapterApp app("ch02", "Spheres");
    app.add_scene("sphere", "a unit sphere 3 units in front of a perspective camera",
                  [] { return sphere_scene(Projection::perspective, Vec3(0, 0, 0), Vec3(0, 0, -3), 1, 45); });
    app.add_scene("sphere-orthographic", "the same sphere seen orthographically from off-axis",
                  [] { return sphere_scene(Projection::orthographic, Vec3(2, 1.5, 0), Vec3(0, 0, -3), 1, 45); });
    app.add_scene("far-sphere", "a unit sphere 10^4 radii away, framed by a narrow field of view", [] {
        // The textbook quadratic loses every digit here in float; the stable one does not.
        return sphere_scene(Projection::perspective, Vec3(0, 0, 0), Vec3(6000, 3000, -7416.198487095663), 1,
                            Real(0.015));
    });
    app.add_scene("inside", "the eye inside a large sphere: every ray takes the far root", [] {
        Scene s = sphere_scene(Projection::perspective, Vec3(0, 0, 0), Vec3(0.5, 0.3, -1), 4, 100);
        s.camera.target = Vec3(0, 0, -1);
        return s;
    });
    return app.run(argc, argv);
}
