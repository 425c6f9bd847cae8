// Chapter 06: shadows (course §9.5): the robust offset, shadow rays, acne measured across
// scales, thin occluders, and the analytic shadow of a sphere.
#include "io/scene_file.hpp"
#include "render/acne.hpp"
#include "render/integrators.hpp"
#include "render/render.hpp"
#include "render/whitted.hpp"
#include "support.hpp"
#include "support/big_ground.hpp"
#include "support/source_dir.hpp"

#include <pcg_random.hpp>

#include <cmath>
#include <random>

using namespace rt;
using rt::test::big_ground_hits;
using rt::test::self_shadow;
using rt::test::SelfShadow;

namespace {

const std::string kScenes = rt::test::source_dir() + "/chapters/ch06_shadows/scenes/";

// A one-light scene with a floor at y = 0 (and whatever `add` puts above it).
Scene floor_scene(Real scale) {
    Scene s = look_at(Vec3(0, 5, 5) * scale, Vec3(0), 40, make_integrator(Shading::whitted));
    s.surfaces.add(
        Polygon({Vec3(-4, 0, -4) * scale, Vec3(-4, 0, 4) * scale, Vec3(4, 0, 4) * scale, Vec3(4, 0, -4) * scale}), 0,
        "floor");
    return s;
}

Scene big_ground(Real radius) {
    Scene scene;
    scene.surfaces.add(Sphere(Vec3(0, -radius, 0), radius), 0, "ground");
    return scene;
}

// The acne of a ground sphere of radius R centred R below the origin (support/big_ground.hpp).
// `bound` scales the error the spawn clears, in machine epsilons of |c|_1 + R: negative for
// the hit record's own (the library's rule).
SelfShadow big_ground_acne(Real radius, Real bound) {
    return self_shadow(big_ground(radius), [&](const HitRecord& rec) {
        return bound < 0 ? rec.error
                         : bound * std::numeric_limits<Real>::epsilon() *
                               (glm::dot(glm::abs(Vec3(0, -radius, 0)), Vec3(1)) + radius);
    });
}

// The same hits and directions through direct_light (exercise 6.2), one directional light
// each, with the shade point the integrator would build, or with its error set to 0 (what a
// shadow ray that drops the bound sees): how many come back black (acne).
SelfShadow big_ground_direct(Real radius, bool keep_error) {
    const Scene scene = big_ground(radius);
    const Material m{Color(0.5f)};
    Sampler sampler(0, 0);
    RayCounters counters;
    TraceContext context{sampler, counters};
    SelfShadow count;
    big_ground_hits(scene, [&](const HitRecord& rec, const Vec3& to_light) {
        const ShadePoint sp{{rec.p, rec.normal, keep_error ? rec.error : 0}, rec.normal, rec.normal, m.diffuse, m};
        Light sun;
        sun.type = Light::Type::directional;
        sun.direction = -to_light;
        ++count.rays;
        count.acne += direct_light(scene, sun, 0, sp, context) == Color(0);
    });
    CHECK(counters.of(RayKind::shadow) == count.rays);
    return count;
}

}  // namespace

TEST_SUITE("ch06") {
TEST_CASE("6.1 offset_origin steps off the surface on n's side, a few ulps of p, at every magnitude") {
    pcg32 rng(6);
    std::uniform_real_distribution<double> u(-1, 1);
    int failures = 0;
    for (int e = -6; e <= 7; ++e)
        for (int k = 0; k < 200; ++k) {
            const Vec3 p = Real(std::pow(10.0, e)) * Vec3{Real(u(rng)), Real(u(rng)), Real(u(rng))};
            const Vec3 n = unit_vector(Vec3{Real(u(rng)), Real(u(rng)), Real(u(rng))});
            const Vec3 q = offset_origin(p, n);
            CAPTURE(p);
            CAPTURE(n);
            CAPTURE(q);
            // Each coordinate moves the way n points (or not at all where n's is tiny) ...
            for (int a = 0; a < 3; ++a) RT_CHECK_FIRST(failures, (q[a] - p[a]) * n[a] >= 0);
            RT_CHECK_FIRST(failures, glm::dot(q - p, n) > 0);
            // ... and by no more than the step's bound: ulps units in the last place of the
            // coordinate, or the fixed step near zero.
            using C = OffsetConstants<Real>;
            for (int a = 0; a < 3; ++a) {
                const Real bound = std::max(Real(C::fixed_step),
                                            Real(2 * C::ulps) * std::numeric_limits<Real>::epsilon() * std::abs(p[a]));
                RT_CHECK_FIRST(failures, std::abs(q[a] - p[a]) <= bound);
            }
        }
    CHECK(failures == 0);
    // Worked value: at 1 on the x axis, float steps 256 ulps of 2^-23 and double 4096 of 2^-52.
    const Vec3 q = offset_origin(Vec3(1, 0, 0), Vec3(1, 0, 0));
    CHECK(q.x == Real(1) + Real(OffsetConstants<Real>::ulps) * std::numeric_limits<Real>::epsilon());
    CHECK(q.y == 0);
}

TEST_CASE("6.1 the robust offset leaves no acne at any scale from 10^0 to 10^5; the naive one does") {
    for (int e = 0; e <= 5; ++e) {
        const Real scale = Real(std::pow(10.0, e));
        CAPTURE(e);
        const AcneCount robust = count_acne(acne_scene(scale, Offset{OffsetMethod::robust}), 160, 120);
        CHECK(robust.lit > 8000);
        CHECK(robust.acne == 0);
        CHECK(robust.leaks == 0);
        // No offset at all (the course's [0, infinity)): the count does see acne.
        const AcneCount naive = count_acne(acne_scene(scale, Offset{OffsetMethod::course, 0}), 160, 120);
        CHECK(naive.acne > 100);
    }
}

TEST_CASE("6.1 a big sphere's error bound: no acne on a ground sphere of radius 10^3 to 10^5") {
    for (int e = 3; e <= 5; ++e) {
        const Real radius = Real(std::pow(10.0, e));
        CAPTURE(radius);
        const SelfShadow with_bound = big_ground_acne(radius, -1);
        CHECK(with_bound.rays > 13000);
        CHECK(with_bound.acne == 0);
        // The reproduction: offset_origin's step alone (no bound) is smaller than the
        // sphere's rounding, in double from 10^3 on (where p's y passes 1/32 the step falls to
        // 2^-45), in float at every radius. Measured, a bound of 1/2 epsilon (double) or 1
        // (float) is the least that clears these rays; kSphereErrorEpsilons = 8 is the margin.
        const SelfShadow step_only = big_ground_acne(radius, 0);
        CHECK(step_only.acne > 1000);
        CHECK(big_ground_acne(radius, Real(0.125)).acne > 0);
    }
}

TEST_CASE("6.1 a thin slab just above a surface still shadows it, at every scale") {
    for (int e = 0; e <= 5; ++e) {
        const Real s = Real(std::pow(10.0, e));
        CAPTURE(e);
        Scene scene = floor_scene(s);
        // A slab 0.001 thick floating 0.001 above the floor, both scaled.
        const Real lo = Real(0.001) * s, hi = Real(0.002) * s;
        scene.surfaces.add(Polygon({Vec3(-1, lo, -1) * Vec3(s, 1, s), Vec3(1, lo, -1) * Vec3(s, 1, s),
                                    Vec3(1, lo, 1) * Vec3(s, 1, s), Vec3(-1, lo, 1) * Vec3(s, 1, s)}));
        scene.surfaces.add(Polygon({Vec3(-1, hi, -1) * Vec3(s, 1, s), Vec3(-1, hi, 1) * Vec3(s, 1, s),
                                    Vec3(1, hi, 1) * Vec3(s, 1, s), Vec3(1, hi, -1) * Vec3(s, 1, s)}));
        const Vec3 p(Real(0.3) * s, 0, Real(-0.2) * s), up(0, 1, 0);
        const Vec3 to_light = unit_vector(Vec3(0.2, 1, 0.1));
        const SpawnedRay robust = spawn_ray({p, up, 0}, to_light, kInfinity, Offset{OffsetMethod::robust});
        CHECK(scene.occluded(robust.ray, robust.interval));
        // The fixed-distance methods skip the slab once epsilon exceeds the gap: what a
        // "safe" large epsilon costs.
        const SpawnedRay big = spawn_ray({p, up, 0}, to_light, kInfinity, Offset{OffsetMethod::normal, Real(0.01) * s});
        CHECK_FALSE(scene.occluded(big.ray, big.interval));
    }
}

TEST_CASE("6.2 direct_light: one shadow ray per light that could add something, none otherwise") {
    Scene scene = floor_scene(1);
    scene.surfaces.add(Sphere(Vec3(0, 2, 0), Real(0.5)), 0, "ball");
    const Material m{Color(0.5f)};
    const ShadePoint lit{{Vec3(2, 0, 2), Vec3(0, 1, 0), 0}, Vec3(0, 1, 0), Vec3(0, 1, 0), m.diffuse, m};
    const ShadePoint under{{Vec3(0, 0, 0), Vec3(0, 1, 0), 0}, Vec3(0, 1, 0), Vec3(0, 1, 0), m.diffuse, m};
    Light above;
    above.position = Vec3(0, 4, 0);
    above.color = Color(1, 0.5f, 0.25f);
    Sampler sampler(0, 0);
    RayCounters counters;
    TraceContext context{sampler, counters};
    // Unblocked: Lambert exactly, c_r c_l (n . l).
    const Vec3 l = unit_vector(above.position - lit.p);
    const Color c = direct_light(scene, above, 0, lit, context);
    CHECK(c.r == doctest::Approx(0.5 * l.y));
    CHECK(c.g == doctest::Approx(0.25 * l.y));
    CHECK(counters.of(RayKind::shadow) == 1);
    // Under the ball: blocked.
    CHECK(direct_light(scene, above, 0, under, context) == Color(0));
    CHECK(counters.of(RayKind::shadow) == 2);
    // A light below the floor, and a black light: nothing to add, no ray cast.
    Light below = above;
    below.position = Vec3(0, -3, 0);
    CHECK(direct_light(scene, below, 0, lit, context) == Color(0));
    Light black = above;
    black.color = Color(0);
    CHECK(direct_light(scene, black, 0, lit, context) == Color(0));
    CHECK(counters.of(RayKind::shadow) == 2);
    // A directional light searches to infinity: a sphere far along it still blocks.
    Light sun;
    sun.type = Light::Type::directional;
    sun.direction = Vec3(0, -1, 0);
    scene.surfaces.add(Sphere(Vec3(2, 1000, 2), Real(1)), 0, "far ball");
    CHECK(direct_light(scene, sun, 0, lit, context) == Color(0));
    // A point light searches only up to the light: the same ball beyond it does not block.
    Light near = above;
    near.position = Vec3(2, 10, 2);
    CHECK(direct_light(scene, near, 0, lit, context) != Color(0));
}

TEST_CASE("6.2 direct_light clears the shade point's error: no self-shadow on a ground sphere of radius 10^3 to 10^5") {
    for (int e = 3; e <= 5; ++e) {
        const Real radius = Real(std::pow(10.0, e));
        CAPTURE(radius);
        const SelfShadow lit = big_ground_direct(radius, true);
        CHECK(lit.rays > 13000);
        CHECK(lit.acne == 0);
        // What a shadow ray that leaves the bound behind sees from the same points: the
        // test above, in double and in float, fails a direct_light that drops it.
        CHECK(big_ground_direct(radius, false).acne > 1000);
    }
}

TEST_CASE("analytic: a sphere's shadow on a plane is the conic of its light cone, pixel for pixel") {
    // conic.json: a ball (centre C, radius R) over the floor y = 0, a point light L, seen from
    // straight above by an orthographic camera. A floor point q is in shadow when the ray
    // from L through q passes within R of C: when q lies inside the cone with apex L, axis
    // a = (C - L)/|C - L| and half-angle asin(R/|C - L|). On the plane that is the conic
    //   ((q - L) . a)^2 - cos^2(alpha) |q - L|^2 >= 0,  (q - L) . a > 0,
    // a quadratic in q's x and z: here an ellipse. Count the pixel centres inside it, and
    // the pixels whose corners disagree (the boundary crosses them): the rendered shadow
    // differs by no more than the boundary pixels.
    const Scene scene = load_scene_file(kScenes + "conic.json");
    const Vec3 C(-0.5, 1.5, 0), L(-2.5, 4, 0.5);
    const Real R = 0.6;
    const Vec3 a = unit_vector(C - L);
    const Real cos2 = 1 - R * R / glm::dot(C - L, C - L);
    const auto in_shadow_at = [&](Real x, Real z) {
        const Vec3 q(x, 0, z);
        const Real along = glm::dot(q - L, a);
        return along > 0 && along * along - cos2 * glm::dot(q - L, q - L) >= 0;
    };
    // The conic's quadratic part in (x, z): an ellipse when B^2 - 4AC < 0.
    const Real A = a.x * a.x - cos2, B = 2 * a.x * a.z, Cq = a.z * a.z - cos2;
    CHECK(B * B - 4 * A * Cq < 0);

    RenderOptions o;
    o.width = 200;
    o.height = 200;
    const Image img = render(scene, o).image;
    const Real half = 4;  // the window is 8 high and square
    const Real pixel = 2 * half / Real(o.width);
    long rendered = 0, analytic = 0, boundary = 0, ball = 0;
    for (int y = 0; y < o.height; ++y)
        for (int i = 0; i < o.width; ++i) {
            // Image row y (from the top) looks at z = -half + (y + 0.5) pixel, since up is -z.
            const Real x = -half + (Real(i) + Real(0.5)) * pixel, z = -half + (Real(y) + Real(0.5)) * pixel;
            if ((x - C.x) * (x - C.x) + (z - C.z) * (z - C.z) <= R * R * Real(1.0001)) {
                ++ball;  // the ball hides the floor here
                continue;
            }
            const bool inside = in_shadow_at(x, z);
            analytic += inside;
            int corners = 0;
            for (int c = 0; c < 4; ++c)
                corners += in_shadow_at(x + (c & 1 ? 1 : -1) * pixel / 2, z + (c & 2 ? 1 : -1) * pixel / 2);
            boundary += corners != 0 && corners != 4;
            // Shadowed floor shows the ambient term alone, 0.2; lit floor more.
            rendered += img.at(i, y).r < 0.2001f;
        }
    CAPTURE(analytic);
    CAPTURE(boundary);
    CHECK(ball > 600);  // pi R^2 / pixel^2 = 707
    CHECK(analytic > 2000);
    CHECK(std::abs(rendered - analytic) <= boundary);
}
}
