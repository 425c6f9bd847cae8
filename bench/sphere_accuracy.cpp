// What book §2.6 quotes of the sphere tests, in the configured Real: the tests' own rays
// (tests/support/sphere_reference.hpp), measured and printed instead of asserted.
//
//   build/release/bin/bench_sphere_accuracy      (Real=double)
//   build/float/bin/bench_sphere_accuracy        (Real=float)
//   bench/sphere_accuracy.py                     (both, and the sentences; ./lab bench precision)
//
// One "key value" line per number: the graded stress test (stable form, 20,000 rays over
// 0.999 of the silhouette of a sphere 10^4 radii away), the common program's comparison of
// both forms (5,000 rays over 0.99), and the analytic area test (an orthographic sphere's
// pixels against pi R^2).
#include "geometry/sphere.hpp"
#include "render/integrators.hpp"
#include "render/render.hpp"
#include "support/sphere_reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

using namespace rt;

namespace {

constexpr Real kEps = std::numeric_limits<Real>::epsilon();

// As tests/support.hpp's rel_error (which brings doctest with it).
Real rel_error(long double got, long double want) {
    return Real(std::fabs(got - want) / std::max(std::fabs(want), 1.0L));
}

// The graded test "2.2 stress: a sphere 10^4 radii away agrees with a long-double reference".
void stress() {
    Real worst = 0;
    int misses = 0, n = 0;
    test::far_sphere_rays(1e4, Real(0.999), 20000, [&](const Ray& r, const Vec3& c) {
        long double ref_near = 0, ref_far = 0;
        if (!test::reference_roots(r, c, 1, ref_near, ref_far)) return;
        ++n;
        Real tn, tf;
        if (!sphere_roots(r, c, 1, tn, tf)) {
            ++misses;
            return;
        }
        worst = std::max({worst, rel_error(tn, ref_near), rel_error(tf, ref_far)});
    });
    std::printf("stress_rays %d\nstress_stable_eps %.6g\nstress_stable_misses %d\n", n, double(worst / kEps), misses);
}

// The common program's "the textbook sphere roots lose digits at a far sphere's silhouette".
void both_forms() {
    Real worst_textbook = 0, worst_stable = 0;
    int textbook_misses = 0, stable_misses = 0, n = 0;
    test::far_sphere_rays(1e4, Real(0.99), 5000, [&](const Ray& r, const Vec3& c) {
        long double ref_near = 0, ref_far = 0;
        if (!test::reference_roots(r, c, 1, ref_near, ref_far)) return;
        ++n;
        Real tn, tf;
        if (sphere_roots_textbook(r, c, 1, tn, tf))
            worst_textbook = std::max(worst_textbook, rel_error(tn, ref_near));
        else
            ++textbook_misses;
        if (sphere_roots(r, c, 1, tn, tf))
            worst_stable = std::max(worst_stable, rel_error(tn, ref_near));
        else
            ++stable_misses;
    });
    std::printf("both_rays %d\ntextbook_eps %.6g\ntextbook_misses %d\nstable_eps %.6g\nstable_misses %d\n", n,
                double(worst_textbook / kEps), textbook_misses, double(worst_stable / kEps), stable_misses);
}

// The test "analytic: an orthographic sphere covers pi R^2 of the window".
void area() {
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
    std::printf("area_covered %d\narea_disk %.6f\narea_perimeter %.6f\n", covered, M_PI * R * R / (pixel * pixel),
                2 * M_PI * R / pixel);
}

}  // namespace

int main(int argc, char**) {
    if (argc != 1) {
        std::fprintf(stderr, "usage: bench_sphere_accuracy (no arguments)\n");
        return 2;
    }
    std::printf("real %s\n", real_name());
    stress();
    both_forms();
    area();
    return 0;
}
