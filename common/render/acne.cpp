#include "render/acne.hpp"

#include "geometry/procedural.hpp"
#include "render/integrators.hpp"
#include "render/render.hpp"

#include <cmath>

namespace rt {

Scene acne_scene(Real scale, const Offset& offset) {
    // Every coordinate is scale * (p + shift): at scale 10^5 the ground's points are near
    // (3, 2, -4) * 10^5, where a float's unit in the last place is about 0.03.
    const Vec3 shift(3, 2, -4);
    const auto at = [&](const Vec3& p) { return scale * (p + shift); };
    Scene s = look_at(at(Vec3(0, 2.2, 7)), at(Vec3(0.6, 0.5, 0)), 40, make_integrator(Shading::whitted));
    s.camera.up = Vec3(0, 1, 0);
    s.background = Color(0.55f, 0.7f, 0.9f);
    s.ambient = Color(0.12f);
    s.offset = offset;
    const MaterialId ground = s.add_material(Material{Color(0.8f, 0.78f, 0.7f)});
    const MaterialId red = s.add_material(Material{Color(0.8f, 0.25f, 0.2f), Color(0.3f), 40});
    const MaterialId blue = s.add_material(Material{Color(0.2f, 0.35f, 0.8f), Color(0.3f), 40});
    s.surfaces.add(Polygon({at(Vec3(-8, 0, -8)), at(Vec3(-8, 0, 8)), at(Vec3(8, 0, 8)), at(Vec3(8, 0, -8))}), ground,
                   "ground");
    s.surfaces.add(Sphere(at(Vec3(0, 1, 0)), scale), red, "sphere");
    s.surfaces.add(Mesh(icosphere(at(Vec3(2.1, 0.8, -0.6)), Real(0.8) * scale, 2)), blue, "icosphere");
    // Low sun from the right: grazing light is where acne shows first.
    Light sun;
    sun.type = Light::Type::directional;
    sun.direction = Vec3(-1, -0.45, -0.35);
    sun.color = Color(0.9f);
    s.lights.push_back(sun);
    return s;
}

AcneCount count_acne(const Scene& scene, int width, int height) {
    const View view = scene.camera.view(width, height);
    const Light& light = scene.lights.at(0);
    AcneCount count;
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            const Ray ray = view.ray(CameraSample{Vec2(Real(i) + Real(0.5), Real(j) + Real(0.5))});
            HitRecord rec;
            if (!scene.hit(ray, Interval{}, rec)) continue;
            const Vec3 side = glm::dot(rec.normal, ray.direction) < 0 ? rec.normal : -rec.normal;
            const LightSample l = light.sample(rec.p);
            if (glm::dot(side, l.direction) <= 0) continue;
            ++count.lit;
            const SpawnedRay s = spawn_ray({rec.p, side, rec.error}, l.direction, l.distance, scene.offset);
            const bool reported = scene.occluded(s.ray, s.interval);
            // The truth: any other (convex) surface across the ray, searched from p itself.
            bool truth = false;
            for (const Surface& other : scene.surfaces.surfaces())
                if (other.id != rec.surface && other.occluded(Ray{rec.p, l.direction}, Interval{0, l.distance}))
                    truth = true;
            count.acne += reported && !truth;
            count.leaks += !reported && truth;
        }
    return count;
}

}  // namespace rt
