#pragma once
// Chapter 02's analytic test and what book §2.6 quotes of it (bench_sphere_accuracy) render
// the same picture: an orthographic camera looking at a sphere of radius 1.3 through a window
// 4 units high, at 400 x 400 pixels, one ray through each pixel's centre. The pixels it
// covers should be the disk's area, pi R^2, to within the pixels its outline crosses.
#include "geometry/sphere.hpp"
#include "render/integrators.hpp"
#include "render/render.hpp"

#include <cmath>
#include <memory>

namespace rt::test {

struct SphereArea {
    int covered;       // pixels whose centre ray hits the sphere
    double disk;       // pi R^2, in pixels
    double perimeter;  // 2 pi R, in pixels: about the pixels the silhouette crosses
};

inline SphereArea orthographic_sphere_area() {
    Scene scene;
    scene.camera.projection = Projection::orthographic;
    scene.camera.eye = Vec3(0, 0, 10);
    scene.camera.target = Vec3(0);
    scene.camera.window_height = 4;
    const Real R = 1.3;
    scene.surfaces.add(Sphere(Vec3(0), R));
    scene.background = Color(0);
    scene.integrator = std::make_shared<NormalIntegrator>();
    RenderOptions o;
    o.width = 400;
    o.height = 400;
    const Image img = render(scene, o).image;
    int covered = 0;
    for (const Color& c : img.pixels) covered += c != Color(0);
    const double pixel = 4.0 / 400;
    return {covered, M_PI * R * R / (pixel * pixel), 2 * M_PI * R / pixel};
}

}  // namespace rt::test
