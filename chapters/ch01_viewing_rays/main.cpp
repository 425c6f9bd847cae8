// Chapter 01: viewing rays. Pictures of the rays themselves, before there is anything to hit.
#include "app/app.hpp"
#include "render/integrators.hpp"

#include <memory>

using namespace rt;

static Scene ray_picture(Projection projection, Real vfov_degrees, std::shared_ptr<const Integrator> integrator) {
    Scene s;
    s.camera.projection = projection;
    s.camera.eye = Vec3(0, 0, 0);
    s.camera.target = Vec3(0, 0, -1);
    s.camera.vertical_fov_degrees = vfov_degrees;
    s.camera.window_height = 2;
    s.integrator = std::move(integrator);
    return s;
}

int main(int argc, char** argv) {
    ChapterApp app("ch01", "Viewing rays");
    app.add_scene("perspective", "directions of perspective rays, 90 degree vertical field of view",
                  [] { return ray_picture(Projection::perspective, 90, std::make_shared<RayDirectionIntegrator>()); });
    app.add_scene("perspective-narrow", "directions of perspective rays, 30 degree field of view",
                  [] { return ray_picture(Projection::perspective, 30, std::make_shared<RayDirectionIntegrator>()); });
    app.add_scene("orthographic", "directions of orthographic rays: all the same",
                  [] { return ray_picture(Projection::orthographic, 0, std::make_shared<RayDirectionIntegrator>()); });
    app.add_scene("orthographic-origins", "origins of orthographic rays across a window 2 units high", [] {
        return ray_picture(Projection::orthographic, 0, std::make_shared<RayOriginIntegrator>(Vec3(0), Real(4)));
    });
    return app.run(argc, argv);
}
