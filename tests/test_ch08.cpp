// Chapter 08: refraction (course §9.7): Snell's law, total internal reflection exactly at
// the critical angle, Schlick, Beer, and the energy a slab transmits.
#include "render/integrators.hpp"
#include "render/render.hpp"
#include "shading/optics.hpp"
#include "support.hpp"

#include <pcg_random.hpp>

#include <cmath>
#include <random>

using namespace rt;

TEST_SUITE("ch08") {
TEST_CASE("8.1 refract: worked values and Snell's law on random rays") {
    Vec3 t;
    // Straight through at normal incidence.
    REQUIRE(refract(Vec3(0, 0, -1), Vec3(0, 0, 1), 1, Real(1.5), t));
    CHECK(t.z == doctest::Approx(-1));
    CHECK(t.x == doctest::Approx(0));
    // 45 degrees into glass: sin(phi) = sin(45)/1.5.
    REQUIRE(refract(unit_vector(Vec3(1, 0, -1)), Vec3(0, 0, 1), 1, Real(1.5), t));
    CHECK(t.x == doctest::Approx(std::sqrt(0.5) / 1.5));
    CHECK(t.z == doctest::Approx(-std::sqrt(1 - 0.5 / 2.25)));
    pcg32 rng(8);
    std::uniform_real_distribution<double> u(-1, 1), ior(1.0, 2.5);
    int failures = 0, total_internal = 0;
    for (int k = 0; k < 2000; ++k) {
        const Vec3 n(0, 0, 1);
        const Vec3 d = unit_vector(Vec3{Real(u(rng)), Real(u(rng)), -Real(std::abs(u(rng))) - Real(0.01)});
        const Real n1 = Real(ior(rng)), n2 = Real(ior(rng));
        if (!refract(d, n, n1, n2, t)) {
            ++total_internal;
            RT_CHECK_FIRST(failures, n1 * std::sqrt(1 - d.z * d.z) > n2 * (1 - 64 * test::kEps));
            continue;
        }
        const Real sin_i = std::sqrt(d.x * d.x + d.y * d.y), sin_t = std::sqrt(t.x * t.x + t.y * t.y);
        RT_CHECK_FIRST(failures, std::abs(n1 * sin_i - n2 * sin_t) <= 1e3 * test::kEps);        // Snell
        RT_CHECK_FIRST(failures, std::abs(glm::length(t) - 1) <= 1e2 * test::kEps);             // unit
        RT_CHECK_FIRST(failures, t.z < 0);                                                      // through
        RT_CHECK_FIRST(failures, std::abs(glm::dot(glm::cross(d, n), t)) <= 1e2 * test::kEps);  // in d and n's plane
    }
    CHECK(failures == 0);
    CHECK(total_internal > 100);
}

TEST_CASE("8.1 total internal reflection starts exactly past the critical angle") {
    for (const Real n1 : {Real(1.33), Real(1.5), Real(2.4)}) {
        const double critical = std::asin(1.0 / double(n1));
        CAPTURE(n1);
        for (const double delta : {1e-3, 1e-5}) {
            Vec3 t;
            const auto at = [](double angle) { return Vec3(Real(std::sin(angle)), 0, Real(-std::cos(angle))); };
            CHECK(refract(at(critical - delta), Vec3(0, 0, 1), n1, 1, t));
            CHECK(std::abs(t.z) < Real(0.1));  // leaving nearly along the surface
            CHECK_FALSE(refract(at(critical + delta), Vec3(0, 0, 1), n1, 1, t));
        }
    }
}

TEST_CASE("8.2 Schlick: R0 at normal incidence, 1 at grazing, rising in between") {
    CHECK(schlick(1, Real(1.5)) == doctest::Approx(0.04));
    CHECK(schlick(1, Real(1.33)) == doctest::Approx((0.33 / 2.33) * (0.33 / 2.33)));
    CHECK(schlick(0, Real(1.5)) == doctest::Approx(1));
    CHECK(schlick(Real(0.5), Real(1.5)) == doctest::Approx(0.04 + 0.96 / 32));
    Real previous = 1;
    for (int k = 0; k <= 20; ++k) {
        const Real r = schlick(Real(k) / 20, Real(1.5));
        CHECK(r <= previous);
        previous = r;
    }
}

TEST_CASE("8.3 Beer: a^s per channel") {
    const Color c = beer(Color(0.5f, 0.25f, 1), 2);
    CHECK(c.r == doctest::Approx(0.25));
    CHECK(c.g == doctest::Approx(0.0625));
    CHECK(c.b == doctest::Approx(1));
    CHECK(beer(Color(0.3f), 0) == Color(1));
    CHECK(beer(Color(0.81f), Real(0.5)).r == doctest::Approx(0.9));
}

TEST_CASE("analytic: the energy through a slab at normal incidence is the series of its internal reflections") {
    // A slab of thickness h, index n, Beer attenuation a per unit, with background 1 behind
    // it and a black wall behind the eye. At normal incidence Schlick gives R = R0, and the
    // light that gets through is
    //   T = (1 - R)^2 a^h sum_k (R^2 a^2h)^k = (1 - R)^2 a^h / (1 - R^2 a^2h),
    // term k taking 2 + 2k bounces. With depth D the renderer sums the terms k <= (D - 2)/2.
    const Real h = 0.5;
    const float a = 0.6f, n = 1.8f;
    Scene s = look_at(Vec3(0, 0, 1), Vec3(0), 40, make_integrator(Shading::whitted));
    s.background = Color(1);
    s.min_reach = 0;  // every term of the series, however small
    Material glass{Color(0)};
    glass.ior = n;
    glass.attenuation = Color(a);
    const MaterialId g = s.add_material(glass);
    const MaterialId black = s.add_material(Material{Color(0)});
    const Real w = 100;
    s.surfaces.add(Polygon({Vec3(-w, -w, 0), Vec3(w, -w, 0), Vec3(w, w, 0), Vec3(-w, w, 0)}), g, "front");
    s.surfaces.add(Polygon({Vec3(-w, -w, -h), Vec3(-w, w, -h), Vec3(w, w, -h), Vec3(w, -w, -h)}), g, "back");
    s.surfaces.add(Polygon({Vec3(-w, -w, 2), Vec3(-w, w, 2), Vec3(w, w, 2), Vec3(w, -w, 2)}), black, "wall");
    const double R = std::pow((n - 1.0) / (n + 1.0), 2), ah = std::pow(double(a), double(h));
    const auto partial = [&](int depth) {
        double sum = 0;
        for (int k = 0; 2 + 2 * k <= depth; ++k) sum += std::pow(R * R * ah * ah, k);
        return (1 - R) * (1 - R) * ah * sum;
    };
    for (int depth : {2, 4, 6, 64}) {
        s.max_depth = depth;
        Sampler sampler(0, 0);
        RayCounters counters;
        TraceContext context{sampler, counters};
        const Color got = s.integrator->Li(s, Ray{Vec3(0, 0, 1), Vec3(0, 0, -1)}, context);
        CAPTURE(depth);
        CHECK(double(got.g) == doctest::Approx(partial(depth)).epsilon(1e-5));
        CHECK(counters.of(RayKind::refraction) >= 2);
    }
    const double closed = (1 - R) * (1 - R) * ah / (1 - R * R * ah * ah);
    CHECK(partial(64) == doctest::Approx(closed).epsilon(1e-12));
}
}
