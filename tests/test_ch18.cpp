// Chapter 18: motion blur (course §9.11.5). Shutter times on worked values and in their
// strata; the swept box of a moving sphere holds it at every time; every search structure
// returns brute force's hit for rays at random times; a ray crossed by a moving ball sees it
// for the share of the exposure the geometry predicts, and so does a floor point its shadow
// crosses. (That nothing moving draws no time is tested in test_render.cpp.)
#include "io/scene_file.hpp"
#include "render/render.hpp"
#include "support.hpp"
#include "support/accel_check.hpp"
#include "support/small_render.hpp"

#include <cmath>
#include <set>

using namespace rt;

TEST_CASE("18.1 shutter_time: stratum k of n, inside the shutter interval") {
    CHECK(shutter_time(0, 4, Real(0.5), 0, 1) == Real(0.125));
    CHECK(shutter_time(3, 4, 0, 0, 1) == Real(0.75));
    CHECK(shutter_time(1, 2, Real(0.5), Real(0.2), Real(0.6)) == doctest::Approx(0.5));
    CHECK(shutter_time(0, 1, Real(0.25), Real(0.25), Real(0.75)) == doctest::Approx(0.375));
    // The largest u below 1 stays below close; an instant shutter gives its one time.
    CHECK(shutter_time(15, 16, 1 - rt::test::kEps / 2, Real(0.2), Real(0.6)) < Real(0.6));
    CHECK(shutter_time(2, 5, Real(0.7), Real(0.4), Real(0.4)) == Real(0.4));
    std::set<int> strata;
    for (int k = 0; k < 16; ++k) {
        const Real t = shutter_time(k, 16, Real(0.3), Real(0.25), Real(0.5));
        CHECK(t >= Real(0.25));
        CHECK(t < Real(0.5));
        strata.insert(int((t - Real(0.25)) / Real(0.25) * 16));
    }
    CHECK(strata.size() == 16);
}

TEST_CASE("18.2 swept_box: the box of both ends holds the sphere at every time") {
    // Centre (1, 2, 3), radius 1, moving by (2, -1, 0): the box of the sphere at time 0,
    // [0, 1, 2] to [2, 3, 4], and at time 1, [2, 0, 2] to [4, 2, 4], together.
    const Sphere s(Vec3(1, 2, 3), 1, Vec3(2, -1, 0));
    const Box b = swept_box(s);
    CHECK(b.min == Vec3(0, 0, 2));
    CHECK(b.max == Vec3(4, 3, 4));
    CHECK(bounding_box(s).min == b.min);  // what the search structures use
    CHECK(bounding_box(s).max == b.max);
    int failures = 0;
    for (int k = 0; k <= 100; ++k) {
        const Real time = Real(k) / 100;
        const Box at = bounding_box(s.at(time));
        CAPTURE(time);
        CAPTURE(at);
        CAPTURE(b);
        for (int i = 0; i < 3; ++i) {
            RT_CHECK_FIRST(failures, at.min[i] >= b.min[i]);
            RT_CHECK_FIRST(failures, at.max[i] <= b.max[i]);
        }
    }
    CHECK(failures == 0);
    // Moving the other way along every axis, and not moving at all: still the smallest box.
    const Box back = swept_box(Sphere(Vec3(1, 2, 3), Real(0.5), Vec3(-3, -2, -1)));
    CHECK(back.min == Vec3(-2.5, -0.5, 1.5));
    CHECK(back.max == Vec3(1.5, 2.5, 3.5));
    const Box still = swept_box(Sphere(Vec3(1, 2, 3), 2));
    CHECK(still.min == Vec3(-1, 0, 1));
    CHECK(still.max == Vec3(3, 4, 5));
}

TEST_CASE("moving spheres: every structure returns brute force's hit at every time") {
    SurfaceList list = rt::test::mixed_scene();
    rt::test::Rng rng;
    for (int k = 0; k < 40; ++k) list.add(Sphere(rng.vec(-6, 6), rng(0.2, 0.7), rng.vec(-3, 3)));
    CHECK(list.moves());
    rt::test::RaySet set = rt::test::random_rays(rt::test::kRandomRays / 2);
    for (Ray& r : set.rays) r.time = rng(0, 1);
    // Brute force tests every sphere; each structure finds a moving one through its box.
    INFO("the moving spheres' boxes come from exercise 18.2 (swept_box)");
    CHECK(rt::test::disagreements(list, set.rays, set.intervals, kAccelKinds) == 0);
    // The reason for the swept box: at time 1 a sphere can stand wholly outside its box at
    // time 0, and a structure built from that box would never test it there.
    const Sphere s(Vec3(0), 1, Vec3(5, 0, 0));
    const Ray late{Vec3(5, 0, 5), Vec3(0, 0, -1), 1};
    SphereHit h;
    CHECK(hit(s.at(late.time), late, Interval{}, h));
    CHECK_FALSE(might_hit(Box{Vec3(-1), Vec3(1)}, late, Interval{}));
    CHECK(might_hit(bounding_box(s), late, Interval{}));
}

TEST_CASE("a ball crossing a ray: seen for the share of the exposure its chord predicts") {
    // A white ball of radius 1 moves from x = -3 at time 0 to x = 3 at time 1 in front of a
    // black background, seen by a narrow orthographic camera along the z axis. The ray through
    // the origin is inside the ball while |6 t - 3| < 1: t in (1/3, 2/3). With the shutter
    // open over [0.25, 0.5], that is (0.5 - 1/3) / 0.25 = 2/3 of the exposure.
    const char* text = R"({"camera": {"projection": "orthographic", "eye": [0, 0, 5], "target": [0, 0, 0],
        "window_height": 0.001, "shutter": [0.25, 0.5]}, "ambient": [1, 1, 1], "background": [0, 0, 0],
      "materials": {"white": {"diffuse": [1, 1, 1]}},
      "surfaces": [{"type": "sphere", "center": [-3, 0, 0], "radius": 1, "moves_to": [3, 0, 0], "material": "white"}]})";
    Scene scene = rt::test::scene_text(text);
    const RenderOptions o = rt::test::jittered(2, 2, 4096);
    const RenderResult r = render(scene, o);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) CHECK(double(r.image.at(x, y).r) == doctest::Approx(2.0 / 3).epsilon(0.005));
    CHECK(r.counters.draws[std::size_t(Dimension::time)] > 0);
    // With the whole of [0, 1] exposed: 1/3.
    scene.camera.shutter_open = 0;
    scene.camera.shutter_close = 1;
    CHECK(double(render(scene, o).image.at(0, 0).r) == doctest::Approx(1.0 / 3).epsilon(0.005));
}

TEST_CASE("a moving ball's shadow: the floor is dark for the share of the time the ball covers the light") {
    // Light travelling along (1, -1, 0); a ball of radius 1 at height 2 moves from x = -3 to
    // x = 3 over the shutter. The floor point P = (4.5, 0, 0) looks towards the light along
    // (-1, 1, 0): that line passes the centre (x, 2, 0) at distance |x - 4.5 + 2| / sqrt(2),
    // so the ball covers the light while x > 4.5 - 2 - sqrt(2), that is for t > t0 =
    // (4.5 - 2 - sqrt(2) + 3) / 6. Straight above P, the camera never sees the ball (it
    // never comes within 1 of x = 4.5). P's brightness: ambient 0.1 plus Lambert's 0.8 / sqrt(2)
    // for the share t0 of the exposure it is lit, since the shadow rays are cast at the
    // camera ray's time.
    const char* text = R"({"camera": {"projection": "orthographic", "eye": [4.5, 10, 0], "target": [4.5, 0, 0],
        "up": [0, 0, -1], "window_height": 0.001}, "shading": "whitted", "ambient": [0.1, 0.1, 0.1],
      "materials": {"white": {"diffuse": [1, 1, 1]}},
      "lights": [{"type": "directional", "direction": [1, -1, 0], "color": [0.8, 0.8, 0.8]}],
      "surfaces": [{"type": "polygon", "vertices": [[-9, 0, -9], [-9, 0, 9], [9, 0, 9], [9, 0, -9]], "material": "white"},
                   {"type": "sphere", "center": [-3, 2, 0], "radius": 1, "moves_to": [3, 2, 0], "material": "white"}]})";
    Scene scene = rt::test::scene_text(text);
    const RenderOptions o = rt::test::jittered(2, 2, 4096);
    const double t0 = (4.5 - 2 - std::sqrt(2.0) + 3) / 6;
    const double want = 0.1 + 0.8 / std::sqrt(2.0) * t0;  // 0.4852
    const Image img = render(scene, o).image;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) CHECK(double(img.at(x, y).r) == doctest::Approx(want).epsilon(0.005));
}

TEST_CASE("a reflection ray sees the scene at the camera ray's time") {
    // An orthographic camera looks down -z at a mirror through the origin with normal
    // (1, 0, 1) / sqrt(2): the reflection leaves along +x. A white ball of radius 0.5 moves
    // along z at x = 3, from z = -3 at time 0 to z = 3 at time 1: it is on the reflected ray
    // at time 0.5 (|z| < 0.5 for t in (5/12, 7/12)), and far from it at time 0.1. With the
    // shutter an instant, the pixel is the ball's white or the black background, whatever time
    // the reflection ray would have had on its own.
    const char* text = R"({"camera": {"projection": "orthographic", "eye": [0, 0, 5], "target": [0, 0, 0],
        "window_height": 0.001, "shutter": [0.5, 0.5]}, "shading": "whitted", "ambient": [1, 1, 1],
      "background": [0, 0, 0],
      "materials": {"mirror": {"diffuse": [0, 0, 0], "mirror": [1, 1, 1]}, "white": {"diffuse": [1, 1, 1]}},
      "surfaces": [{"type": "polygon", "vertices": [[-1, -1, 1], [1, -1, -1], [1, 1, -1], [-1, 1, 1]], "material": "mirror"},
                   {"type": "sphere", "center": [3, 0, -3], "radius": 0.5, "moves_to": [3, 0, 3], "material": "white"}]})";
    Scene scene = rt::test::scene_text(text);
    const RenderOptions o = rt::test::jittered(2, 2, 4);
    CHECK(double(render(scene, o).image.at(0, 0).r) == doctest::Approx(1));
    scene.camera.shutter_open = scene.camera.shutter_close = Real(0.1);
    CHECK(double(render(scene, o).image.at(0, 0).r) == doctest::Approx(0));
}
