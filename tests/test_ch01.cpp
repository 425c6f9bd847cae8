// Chapter 01: viewing rays (course §9.2).
#include "render/camera.hpp"
#include "support.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <pcg_random.hpp>

#include <random>

using namespace rt;
using rt::test::kEps;

TEST_SUITE("ch01") {
TEST_CASE("1.1 camera_basis is orthonormal, right-handed, and looks down -w") {
    const Vec3 dir(1, -2, -3);  // deliberately not unit length
    const Basis b = camera_basis(dir, Vec3(0, 1, 0));
    CHECK(glm::length(b.u) == doctest::Approx(1).epsilon(4 * kEps));
    CHECK(glm::length(b.v) == doctest::Approx(1).epsilon(4 * kEps));
    CHECK(glm::length(b.w) == doctest::Approx(1).epsilon(4 * kEps));
    CHECK(std::abs(glm::dot(b.u, b.v)) < 8 * kEps);
    CHECK(std::abs(glm::dot(b.v, b.w)) < 8 * kEps);
    CHECK(std::abs(glm::dot(b.u, b.w)) < 8 * kEps);
    const Vec3 uxv = glm::cross(b.u, b.v);  // right-handed: u x v = w
    CHECK(glm::length(uxv - b.w) < 8 * kEps);
    const Vec3 back = -glm::normalize(dir);
    CHECK(glm::length(b.w - back) < 4 * kEps);
    CHECK(glm::dot(b.v, Vec3(0, 1, 0)) > 0);               // v is "up" on screen
    CHECK(b.u.y == doctest::Approx(0).epsilon(4 * kEps));  // u is level: perpendicular to up
}

TEST_CASE("1.1 camera_basis of the standard camera is the world frame") {
    const Basis b = camera_basis(Vec3(0, 0, -1), Vec3(0, 1, 0));
    CHECK(b.u == Vec3(1, 0, 0));
    CHECK(b.v == Vec3(0, 1, 0));
    CHECK(b.w == Vec3(0, 0, 1));
}

// Exercise 1.2's tolerance (render/camera.hpp): 4 machine epsilons of the window's size,
// |l| + |r| for u and |b| + |t| for v, however the map is arranged.
doctest::Approx window_coordinate(double want, Real low, Real high) {
    return doctest::Approx(want).epsilon(4 * kEps).scale(std::abs(low) + std::abs(high));
}

TEST_CASE("1.2 window_point maps pixel centres per course §9.2") {
    // A 4x3 image on the window [-2, 2] x [-1.5, 1.5]: pixels are exactly 1 unit square.
    const Window win{-2, 2, -1.5, 1.5};
    const auto u = [&](double want) { return window_coordinate(want, win.l, win.r); };
    const auto v = [&](double want) { return window_coordinate(want, win.b, win.t); };
    const Vec2 first = window_point(0.5, 0.5, 4, 3, win);  // centre of pixel (0, 0)
    CHECK(first.x == u(-1.5));
    CHECK(first.y == v(-1));
    const Vec2 last = window_point(3.5, 2.5, 4, 3, win);  // centre of pixel (3, 2)
    CHECK(last.x == u(1.5));
    CHECK(last.y == v(1));
    // The image's outer edges are the window's edges.
    const Vec2 bottom_left = window_point(0, 0, 4, 3, win), top_right = window_point(4, 3, 4, 3, win);
    CHECK(bottom_left.x == u(-2));
    CHECK(bottom_left.y == v(-1.5));
    CHECK(top_right.x == u(2));
    CHECK(top_right.y == v(1.5));

    // u_s = l + (r - l)(i + 0.5)/n_x for every pixel of an odd-sized image on an offset window.
    const Window w2{1, 3, -5, -4};
    for (int i = 0; i < 7; ++i)
        for (int j = 0; j < 5; ++j) {
            const Vec2 p = window_point(Real(i) + Real(0.5), Real(j) + Real(0.5), 7, 5, w2);
            CAPTURE(i);
            CAPTURE(j);
            CHECK(p.x == window_coordinate(1 + 2 * (i + 0.5) / 7, w2.l, w2.r));
            CHECK(p.y == window_coordinate(-5 + 1 * (j + 0.5) / 5, w2.b, w2.t));
        }
}

TEST_CASE("1.2 the centre pixel of an odd image looks straight ahead") {
    // (0, 0) to within the tolerance: fma(x, (r - l)/nx, l) gives -5.55e-17 here, and is right.
    const Window win{-1, 1, -1, 1};
    const Vec2 centre = window_point(Real(1.5), Real(1.5), 3, 3, win);
    CHECK(centre.x == window_coordinate(0, win.l, win.r));
    CHECK(centre.y == window_coordinate(0, win.b, win.t));
}

TEST_CASE("1.3 orthographic rays are parallel and start on the eye's plane") {
    const Vec3 eye(1, 2, 3);
    const Basis b = camera_basis(Vec3(0, 0, -1), Vec3(0, 1, 0));
    const Ray r1 = orthographic_ray(eye, b, Vec2(-1, 0.5));
    const Ray r2 = orthographic_ray(eye, b, Vec2(2, -3));
    CHECK(r1.direction == -b.w);
    CHECK(r2.direction == -b.w);
    CHECK(r1.origin == Vec3(0, 2.5, 3));
    CHECK(r2.origin == Vec3(3, -1, 3));
}

TEST_CASE("1.4 perspective rays leave the eye and reach the image plane at t = 1") {
    const Vec3 eye(1, 2, 3);
    const Basis b = camera_basis(Vec3(1, 1, -1), Vec3(0, 1, 0));
    const Real d = 2.5;
    const Vec2 uv(0.75, -0.25);
    const Ray r = perspective_ray(eye, b, d, uv);
    CHECK(r.origin == eye);
    const Vec3 s = r.at(1) - eye;  // s - e, in uvw coordinates: (u_s, v_s, -d)
    CHECK(glm::dot(s, b.u) == doctest::Approx(0.75).epsilon(8 * kEps));
    CHECK(glm::dot(s, b.v) == doctest::Approx(-0.25).epsilon(8 * kEps));
    CHECK(glm::dot(s, b.w) == doctest::Approx(-2.5).epsilon(8 * kEps));
}

TEST_CASE("1.4 the direction is relative to the eye: a camera 10^5 from the origin keeps its digits") {
    // The same frame and window point with the eye far away: the direction u_s u + v_s v - d w
    // does not depend on the eye, so its uvw coordinates keep the 8 epsilons. Computed as
    // s - e, with s = e + u_s u + v_s v - d w first, it keeps only what the eye's size leaves.
    const Basis b = camera_basis(Vec3(1, 1, -1), Vec3(0, 1, 0));
    for (const Vec3 eye : {Vec3(1e5, -2e5, 3e5), Vec3(-4e4, 7e4, 1e5)}) {
        const Ray r = perspective_ray(eye, b, Real(2.5), Vec2(0.75, -0.25));
        CAPTURE(eye);
        CAPTURE(r.direction);
        CHECK(r.origin == eye);
        CHECK(glm::dot(r.direction, b.u) == doctest::Approx(0.75).epsilon(8 * kEps));
        CHECK(glm::dot(r.direction, b.v) == doctest::Approx(-0.25).epsilon(8 * kEps));
        CHECK(glm::dot(r.direction, b.w) == doctest::Approx(-2.5).epsilon(8 * kEps));
    }
}

TEST_CASE("View: the field of view is the angle the rays actually span (analytic)") {
    // Independent of the window formulas: the ray through the middle of the top edge of the
    // image makes half the vertical field of view with the view direction, for any aspect.
    for (Real fov : {Real(10), Real(45), Real(90), Real(150)}) {
        Camera cam;
        cam.eye = Vec3(0.5, -1, 2);
        cam.target = Vec3(3, 1, -4);
        cam.vertical_fov_degrees = fov;
        const View v = cam.view(640, 360);
        const Vec3 ahead = glm::normalize(cam.target - cam.eye);
        const Vec3 top = glm::normalize(v.ray({Vec2(320, 360)}).direction);
        const Vec3 side = glm::normalize(v.ray({Vec2(640, 180)}).direction);
        CAPTURE(fov);
        CHECK(std::acos(glm::dot(top, ahead)) == doctest::Approx(glm::radians(fov) / 2).epsilon(1e-5));
        // Square pixels: tan(horizontal half angle) = aspect * tan(vertical half angle).
        CHECK(std::tan(std::acos(glm::dot(side, ahead))) ==
              doctest::Approx(Real(640) / 360 * std::tan(glm::radians(fov) / 2)).epsilon(1e-4));
    }
}

TEST_CASE("View: an orthographic window keeps its height and takes its width from the aspect") {
    Camera cam;
    cam.projection = Projection::orthographic;
    cam.window_height = 3;
    const View v = cam.view(200, 100);
    CHECK(v.window.t - v.window.b == doctest::Approx(3));
    CHECK(v.window.r - v.window.l == doctest::Approx(6));
    // Pixel (0, 0) is the bottom-left one: its ray starts at the bottom-left of the window.
    const Ray r = v.pixel_ray(0, 0);
    CHECK(r.origin.x == doctest::Approx(-3 + 0.015));
    CHECK(r.origin.y == doctest::Approx(-1.5 + 0.015));
}

TEST_CASE("View: a camera sample's film position and time reach the ray; the pinhole ignores the lens") {
    Camera cam;
    const View v = cam.view(40, 20);
    const Ray centre = v.pixel_ray(20, 10);  // the pixel centre (20.5, 10.5): time 0
    CHECK(centre.time == 0);
    CameraSample s{Vec2(Real(20.5), Real(10.5)), Vec2(Real(0.9), Real(-0.3)), Real(0.25)};
    const Ray r = v.ray(s);
    CHECK(r.time == Real(0.25));
    CHECK(r.origin == centre.origin);  // no lens yet: the lens position changes nothing
    CHECK(r.direction == centre.direction);
    s.film = Vec2(0, 0);  // the bottom-left corner of the image
    CHECK(v.ray(s).direction.x < 0);
    CHECK(v.ray(s).direction.y < 0);
}

TEST_CASE("stress: every pixel's ray passes through its window point, cameras at scales 1 to 1e5") {
    pcg32 rng(2024);
    std::uniform_real_distribution<double> unit(-1, 1);
    int checked = 0, failures = 0;
    for (double scale : {1.0, 1e2, 1e5}) {
        for (int k = 0; k < 50; ++k) {
            Camera cam;
            cam.eye = Vec3{Real(scale * unit(rng)), Real(scale * unit(rng)), Real(scale * unit(rng))};
            cam.target = cam.eye + Vec3{Real(unit(rng)), Real(unit(rng)), Real(unit(rng))};
            cam.vertical_fov_degrees = Real(20 + 100 * (unit(rng) + 1) / 2);
            const View v = cam.view(37, 23);
            for (int i = 0; i < 37; i += 6)
                for (int j = 0; j < 23; j += 5) {
                    const Ray r = v.pixel_ray(i, j);
                    const Vec3 s = r.direction;  // = s - e, exactly (u_s, v_s, -d) in uvw
                    const Vec2 want = window_point(Real(i) + Real(0.5), Real(j) + Real(0.5), 37, 23, v.window);
                    // Directions are relative to the eye, so the eye's size does not enter.
                    CAPTURE(scale);
                    CAPTURE(cam.eye);
                    CAPTURE(i);
                    CAPTURE(j);
                    RT_CHECK_FIRST(failures,
                                   std::abs(glm::dot(s, v.uvw.u) - want.x) < 16 * kEps * (1 + std::abs(want.x)));
                    RT_CHECK_FIRST(failures,
                                   std::abs(glm::dot(s, v.uvw.v) - want.y) < 16 * kEps * (1 + std::abs(want.y)));
                    ++checked;
                }
        }
    }
    CHECK(checked == 3 * 50 * 7 * 5);
    CHECK(failures == 0);
}

// Book §1.6, "Why not a perspective matrix?": the same cameras as the stress test, 100 units
// from the origin, their rays taken the rasteriser's way instead: the pixel's corner of the
// view volume carried back through the inverse of projection x view, with near and far
// planes at 1e-3 and 1e3. The frame's rays meet the stress test's bound; the matrix's miss
// it by more than a thousand times, in float and in double alike.
TEST_CASE("matrix: a ray unprojected through an inverse perspective matrix loses what the frame keeps") {
    pcg32 rng(2024);
    std::uniform_real_distribution<double> unit(-1, 1);
    const Real near_plane = Real(1e-3), far_plane = Real(1e3), bound = 16 * kEps;
    double worst_frame = 0, worst_matrix = 0;  // relative error of (u_s, v_s), in units of epsilon
    for (int k = 0; k < 50; ++k) {
        Camera cam;
        cam.eye = Vec3{Real(1e2 * unit(rng)), Real(1e2 * unit(rng)), Real(1e2 * unit(rng))};
        cam.target = cam.eye + Vec3{Real(unit(rng)), Real(unit(rng)), Real(unit(rng))};
        cam.vertical_fov_degrees = Real(20 + 100 * (unit(rng) + 1) / 2);
        const View v = cam.view(37, 23);
        using Mat4 = glm::mat<4, 4, Real>;
        using Vec4 = glm::vec<4, Real>;
        const Mat4 inverse = glm::inverse(
            glm::perspective(glm::radians(cam.vertical_fov_degrees), Real(37) / Real(23), near_plane, far_plane) *
            glm::lookAt(cam.eye, cam.target, cam.up));
        for (int i = 0; i < 37; i += 6)
            for (int j = 0; j < 23; j += 5) {
                const Vec2 want = window_point(Real(i) + Real(0.5), Real(j) + Real(0.5), 37, 23, v.window);
                // The same point of the image in normalised device coordinates, [-1, 1]^2.
                const Real x = want.x / v.window.r, y = want.y / v.window.t;
                const Vec4 n = inverse * Vec4(x, y, -1, 1), f = inverse * Vec4(x, y, 1, 1);
                const Vec3 from_matrix = Vec3(f) / f.w - Vec3(n) / n.w;
                // Each direction's window point: where it meets the plane at the focal distance.
                auto error = [&](const Vec3& d) {
                    const double depth = -double(glm::dot(d, v.uvw.w)) / double(v.focal_distance);
                    const double du = double(glm::dot(d, v.uvw.u)) / depth - double(want.x);
                    const double dv = double(glm::dot(d, v.uvw.v)) / depth - double(want.y);
                    return std::max(std::abs(du) / (1 + std::abs(double(want.x))),
                                    std::abs(dv) / (1 + std::abs(double(want.y)))) /
                           double(kEps);
                };
                worst_frame = std::max(worst_frame, error(v.pixel_ray(i, j).direction));
                const double m = error(from_matrix);
                worst_matrix = std::max(worst_matrix, std::isfinite(m) ? m : HUGE_VAL);
            }
    }
    CAPTURE(worst_frame);
    CAPTURE(worst_matrix);
    CHECK(worst_frame < double(bound / kEps));
    CHECK(worst_matrix > 1000 * double(bound / kEps));
}
}  // TEST_SUITE("ch01")
