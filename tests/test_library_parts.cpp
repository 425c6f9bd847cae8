// Library code of chapters 13 and 14 that no exercise touches, tested in the common
// executable so that the chapters' own tests all depend on the exercises (with the stubs,
// every one of them fails): drop_thin and the refusal of operands that are not solids
// (book §13), and the statistical image test of tools/ztest.hpp (book §14.6). Also evidence
// the book cites that needs the reference exercises, not a student's: the textbook sphere
// roots' lost digits (book §2.6).
#include "geometry/procedural.hpp"
#include "geometry/shape.hpp"
#include "geometry/sphere.hpp"
#include "io/scene_file.hpp"
#include "render/render.hpp"
#include "render/strata.hpp"
#include "support.hpp"
#include "support/span_check.hpp"
#include "support/sphere_reference.hpp"
#include "ztest.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

using namespace rt;

using rt::test::Pairs;
using rt::test::share;
using rt::test::span_list;
using rt::test::ts;

TEST_CASE("drop_thin drops slivers of solid and closes slivers of air, in world lengths") {
    SpanList s = span_list({{0, 1}, {1 + Real(1e-9), 2}, {3, 3 + Real(1e-9)}, {4, 5}});
    SpanList kept = s;
    drop_thin(kept, Real(1e-6), Vec3(0, 2, 0));  // |d| = 2: thicknesses count double
    CHECK(ts(kept) == Pairs{{0, 2}, {4, 5}});
    kept = s;
    drop_thin(kept, 0, Vec3(0, 2, 0));  // thin 0: everything stays
    CHECK(kept.size() == 4);
    // A span 0.4 long along d = (0, 0, 3) is 1.2 long in the world: kept at thin 1, not at 1.5.
    SpanList w = span_list({{0, Real(0.4)}});
    drop_thin(w, 1, Vec3(0, 0, 3));
    CHECK(w.size() == 1);
    drop_thin(w, Real(1.5), Vec3(0, 0, 3));
    CHECK(w.empty());
}

TEST_CASE("operands that are not closed solids are refused, naming them") {
    const auto poly = share(Polygon({Vec3(0), Vec3(1, 0, 0), Vec3(0, 1, 0)}));
    const auto ball = share(Sphere(Vec3(0), 1));
    CHECK_THROWS_WITH_AS(Csg(CsgOp::union_of, {ball}, {poly, kNone, "sheet"}),
                         doctest::Contains("\"sheet\" is not a closed solid: a polygon has no inside"),
                         std::invalid_argument);
    CHECK_THROWS_AS(Csg(CsgOp::union_of, {share(Triangle(Vec3(0), Vec3(1, 0, 0), Vec3(0, 1, 0)))}, {ball}),
                    std::invalid_argument);
    CHECK_THROWS_WITH_AS(Csg(CsgOp::difference, {ball}, {share(Mesh(terrain(Vec3(0), 2, Real(0.2), 4)))}),
                         doctest::Contains("not closed"), std::invalid_argument);
    CHECK_THROWS_AS(Csg(CsgOp::difference, {ball}, {share(Instance(poly, Affine::translate(Vec3(1, 0, 0))))}),
                    std::invalid_argument);
    // A closed mesh with one triangle removed is open.
    MeshData cube = subdivided_cube(Vec3(0), 1, 1);
    cube.triangles.pop_back();
    CHECK_THROWS_AS(Csg(CsgOp::union_of, {ball}, {share(Mesh(cube))}), std::invalid_argument);

    const std::string text = R"({"camera": {"eye": [0, 0, 5], "target": [0, 0, 0]},
 "surfaces": [{"type": "csg", "op": "difference", "operands": [
   {"type": "sphere", "center": [0, 0, 0], "radius": 1},
   {"type": "polygon", "name": "lid", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}]}]})";
    try {
        load_scene_text(text, "lid.json", ".");
        FAIL("expected a SceneError");
    } catch (const SceneError& e) {
        const std::string what = e.what();
        CHECK(what.find("lid.json:4:4: /surfaces/0/operands/1: a CSG operand must be a closed solid: 'lid': a "
                        "polygon has no inside") == 0);
        CHECK(what.find('\n') == std::string::npos);
    }
}

TEST_CASE("the statistical test: Sidak's level, Student's t, and a verdict on known numbers") {
    // Sidak: 1 - (1 - alpha)^(1/N); for small alpha close to alpha / N.
    CHECK(stat::sidak(0.01, 1) == doctest::Approx(0.01));
    CHECK(stat::sidak(0.01, 10000) == doctest::Approx(1.005e-6).epsilon(1e-3));
    // Student's t against closed forms: with 1 degree of freedom P(|T| > t) = (2/pi) atan(1/t),
    // with 2 it is 2 / (s (s + t)), s = sqrt(2 + t^2); far into the tails too.
    for (double t : {0.3, 1.0, 4.0, 1e3, 1e6}) {
        CAPTURE(t);
        CHECK(stat::t_tail(t, 1) == doctest::Approx(2 / std::numbers::pi * std::atan(1 / t)).epsilon(1e-12));
        const double s = std::sqrt(2 + t * t);
        CHECK(stat::t_tail(t, 2) == doctest::Approx(2 / (s * (s + t))).epsilon(1e-12));
    }
    // Table quantiles: t(0.975; 60) = 2.000298, t(0.995; 30) = 2.749996, t(0.9995; 10) = 4.586894.
    CHECK(stat::t_tail(2.000298, 60) == doctest::Approx(0.05).epsilon(1e-5));
    CHECK(stat::t_tail(2.749996, 30) == doctest::Approx(0.01).epsilon(1e-5));
    CHECK(stat::t_tail(4.586894, 10) == doctest::Approx(0.001).epsilon(1e-5));
    // Far more degrees of freedom: the normal distribution's tails, P(|Z| > 3.290527) = 0.001.
    CHECK(stat::t_tail(3.290527, 1e6) == doctest::Approx(0.001).epsilon(1e-4));
    CHECK(stat::t_tail(3.290527, 1e12) == doctest::Approx(0.001).epsilon(1e-5));
    // The same deviation is far likelier under t: why a variance from 64 renders needs it.
    CHECK(stat::t_tail(4.87, 63) > 5 * stat::t_tail(4.87, 1e9));

    // An average of 4 renders of variance 4 has standard deviation 1. Variance taken as exact
    // (0 renders): the normal's P(|Z| > 1.959964) = 0.05.
    CHECK(stat::p_value(1.959964, 4, 0, 4, 0, 0) == doctest::Approx(0.05).epsilon(1e-5));
    CHECK(stat::p_value(-3.290527, 4, 0, 4, 0, 0) == doctest::Approx(0.001).epsilon(1e-5));
    // Estimated from 11 renders: t with 10 degrees of freedom, t(0.975; 10) = 2.228139.
    CHECK(stat::p_value(2.228139, 4, 0, 4, 0, 11) == doctest::Approx(0.05).epsilon(1e-5));
    // A floor as large as the noise: spread 2, and 10 (2 / 1)^2 = 40 degrees of freedom,
    // t(0.975; 40) = 2.021075.
    CHECK(stat::p_value(2.021075 * std::sqrt(2.0), 4, 0, 4, 1, 11) == doctest::Approx(0.05).epsilon(1e-5));
    // Nothing varies: equal is a pass, any difference a failure; NaN is a failure.
    CHECK(stat::p_value(5, 8, 5, 0, 0, 64) == 1);
    CHECK(stat::p_value(5.001, 8, 5, 0, 0, 64) == 0);
    CHECK(stat::p_value(std::nan(""), 8, 5, 1, 0.004, 64) == 0);
    // One list's variance about the mean of 4.
    const stat::MeanVar mv = stat::mean_var({{1, 5}, {2, 5}, {3, 5}, {4, 5}});
    CHECK(mv.mean[0] == doctest::Approx(2.5));
    CHECK(mv.var[0] == doctest::Approx((1.5 * 1.5 * 2 + 0.5 * 0.5 * 2) / 3));
    CHECK(mv.var[1] == 0);

    // 1000 values: the image fails on the smallest p alone, however few values are off.
    const stat::MeanVar ref{std::vector<double>(1000, 0.5), std::vector<double>(1000, 1e-3)};
    std::vector<std::vector<double>> renders(8, std::vector<double>(1000, 0.5));
    for (std::size_t k = 0; k < renders.size(); ++k) renders[k][3] += k % 2 ? 0.02 : -0.02;  // noise, mean kept
    stat::Verdict v = stat::compare(renders, ref, 0.01, 0, 64);
    CHECK(v.level == doctest::Approx(stat::sidak(0.01, 1000)));
    CHECK(v.failed == 0);
    CHECK(v.pass());
    // Off by 4.6 standard deviations of the average: p = 2.1e-5 under t with 63 degrees of
    // freedom, above the level of 1.0e-5, but 4.2e-6 for the normal z-test, below it.
    for (auto& r : renders) r[17] = 0.5 + 4.6 * std::sqrt(1e-3 / 8);
    v = stat::compare(renders, ref, 0.01, 0, 64);
    CHECK(v.failed == 0);
    CHECK(v.smallest_p > v.level);
    CHECK(v.pass());
    CHECK_FALSE(stat::compare(renders, ref, 0.01, 0, 0).pass());
    // One value far off: the image fails, as it would with many.
    for (auto& r : renders) r[18] = 0.6;
    v = stat::compare(renders, ref, 0.01, 0, 64);
    CHECK(v.failed == 1);
    CHECK(v.smallest_p < v.level);
    CHECK_FALSE(v.pass());
    // A floor of 0.04 makes that 0.1 rounding-sized: it passes.
    CHECK(stat::compare(renders, ref, 0.01, 0.04, 64).pass());
}

// Chapters 16 and 18: what needs none of their exercises (the stubs must fail every test of
// a chapter's own program).
TEST_CASE("scene files: a lens needs a perspective camera and an aperture") {
    CHECK_THROWS_WITH(load_scene_text(R"({"camera": {"projection": "orthographic", "eye": [0, 0, 3],
        "target": [0, 0, 0], "aperture": 0.2}, "surfaces": []})",
                                      "o.json", "."),
                      doctest::Contains("a lens (aperture > 0) needs a perspective camera"));
    CHECK_THROWS_WITH(load_scene_text(R"({"camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "lens": "disk"},
        "surfaces": []})",
                                      "l.json", "."),
                      doctest::Contains("a lens needs an aperture > 0"));
    CHECK_THROWS_WITH(load_scene_text(R"({"camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "aperture": 1,
        "lens": "hexagon"}, "surfaces": []})",
                                      "h.json", "."),
                      doctest::Contains("/camera/lens: unknown lens \"hexagon\" (expected square or disk)"));
}

TEST_CASE("--stats: nothing moving draws no time sample") {
    const char* text = R"({"camera": {"eye": [0, 0, 3], "target": [0, 0, 0]},
      "surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]})";
    Scene scene = load_scene_text(text, "still.json", ".");
    scene.build_accel(AccelKind::fast);
    CHECK_FALSE(scene.surfaces.moves());
    RenderOptions o;
    o.width = 8;
    o.height = 6;
    o.spp = 4;
    const RenderResult r = render(scene, o);
    CHECK(r.counters.draws[std::size_t(Dimension::time)] == 0);
    CHECK(r.counters.draws[std::size_t(Dimension::lens)] == 0);
    CHECK(r.counters.draws[std::size_t(Dimension::light)] == 0);
}

TEST_CASE("Cuboid: crossings, a ray in a face's plane, the exit from inside") {
    const Cuboid box(Vec3(-1, -2, -3), Vec3(1, 2, 3));
    CuboidHit enter, leave;
    REQUIRE(cuboid_crossings(box, Ray{Vec3(-5, 0, 0), Vec3(2, 0, 0)}, enter, leave));
    CHECK(enter.t == 2);  // x = -1 at t = 2 (|d| = 2)
    CHECK(enter.axis == 0);
    CHECK(enter.side == -1);
    CHECK(leave.t == 3);
    CHECK(leave.side == 1);
    // Starting inside: the first crossing in [0, inf) is the exit, through the +z face.
    CuboidHit h;
    REQUIRE(hit(box, Ray{Vec3(0.5, 0.5, 0), Vec3(0, 0, 1)}, Interval{0, kInfinity}, h));
    CHECK(h.t == 3);
    CHECK(h.axis == 2);
    CHECK(h.side == 1);
    HitRecord rec = record(box, Ray{Vec3(0.5, 0.5, 0), Vec3(0, 0, 1)}, h);
    CHECK(rec.normal == Vec3(0, 0, 1));
    // Direction components of +0 and -0 with the origin off the slab: a miss, never a NaN hit.
    CHECK_FALSE(cuboid_crossings(box, Ray{Vec3(5, 0, -9), Vec3(0, 0, 1)}, enter, leave));
    CHECK_FALSE(cuboid_crossings(box, Ray{Vec3(5, 0, -9), Vec3(-0.0, 0, 1)}, enter, leave));
    // Inside the slab, parallel to it: the other slabs decide.
    REQUIRE(cuboid_crossings(box, Ray{Vec3(0.25, 0, -9), Vec3(0, 0, 1)}, enter, leave));
    CHECK(enter.t == 6);
    CHECK(leave.t == 12);
}

TEST_CASE("two boxes sharing a face: one solid in a union, closed by the thin tolerance") {
    // Two unit boxes side by side along x, each turned and moved back by its own transform,
    // so the shared face is computed twice with different rounding. A ray along x through
    // both is one span by default; with "thin" 0 the sliver of air between them may stay.
    const Affine turn = Affine::rotate(Vec3(1, 2, 3), 37).then(Affine::translate(Vec3(300, -200, 100)));
    const Affine back = inverse(turn, "test");
    const auto left =
        share(Instance(share(Instance(share(Cuboid(Vec3(-1, -0.5, -0.5), Vec3(0, 0.5, 0.5))), turn)), back));
    const auto right =
        share(Instance(share(Instance(share(Cuboid(Vec3(0, -0.5, -0.5), Vec3(1, 0.5, 0.5))), turn)), back));
    const Shape joined = Csg(CsgOp::union_of, CsgOperand{left}, CsgOperand{right});
    int one_span = 0;
    for (int k = 0; k < 200; ++k) {
        const Real y = Real(k % 20) * Real(0.045) - Real(0.43), z = Real(k / 20) * Real(0.09) - Real(0.41);
        SpanList s;
        spans(joined, Ray{Vec3(-5, y, z), Vec3(1, 0, 0)}, s);
        CHECK(s.size() >= 1);
        one_span += s.size() == 1;
        if (s.size() == 1) {
            // To the rounding of coordinates near (300, -200, 100), where the boxes went and came back.
            CHECK(std::abs(s[0].in.t - 4) <= 64 * rt::test::kEps * 400);
            CHECK(std::abs(s[0].out.t - 6) <= 64 * rt::test::kEps * 400);
        }
    }
    CHECK(one_span == 200);
}

TEST_CASE("Sampler: only a sample's first point in a dimension takes its stratum") {
    // A second glossy bounce or a second area light in the same sample gets an independent
    // point: one tied to the first stratum would bias a path that depends on both.
    Sampler s(4, 2);
    s.set_strata(16, 4, Strata::jittered);
    s.start_sample(3);
    CHECK(s.take_stratum(Dimension::glossy));
    CHECK_FALSE(s.take_stratum(Dimension::glossy));
    CHECK_FALSE(s.take_stratum(Dimension::glossy));
    CHECK(s.take_stratum(Dimension::light));  // each dimension its own
    s.start_sample(4);
    CHECK(s.take_stratum(Dimension::glossy));  // and each sample
    Sampler plain(4, 2);
    plain.set_strata(10, 0, Strata::jittered);  // 10 is not a square: no strata at all
    CHECK(plain.strata() == Strata::none);
    plain.start_sample(0);
    CHECK_FALSE(plain.take_stratum(Dimension::lens));
}

TEST_CASE("Sampler: a second point in a dimension is independent of the first") {
    // Two glossy points per sample, 16 jittered samples per pixel, over 2,000 pixels: if the
    // second took the first's stratum, x1 and x2 would share a quarter of [0, 1), and E[x1 x2]
    // would be about the mean square of the four stratum centres, 0.328; independent, 0.25.
    double sum = 0;
    int n = 0;
    for (std::uint64_t pixel = 0; pixel < 2000; ++pixel) {
        Sampler s(9, pixel);
        s.set_strata(16, 4, Strata::jittered);
        for (int k = 0; k < 16; ++k) {
            s.start_sample(k);
            const Vec2 a = sample_square(s, Dimension::glossy), b = sample_square(s, Dimension::glossy);
            sum += double(a.x) * double(b.x);
            ++n;
        }
    }
    // 32,000 products of spread about 0.2: the mean is 0.25 to within 0.004 (3.5 sigma).
    CHECK(std::abs(sum / n - 0.25) < 0.004);
}

TEST_CASE("the textbook sphere roots lose digits at a far sphere's silhouette (why exercise 2.2 exists)") {
    // Evidence for book §2.6, not a grade: the common program links every exercise from
    // solutions/, so this compares the reference's 2.1 (the course's formula, as printed)
    // with its 2.2 on the same rays. A student's 2.1 is not asked to be inaccurate.
    Real worst_textbook = 0, worst_stable = 0;
    int textbook_misses = 0;
    rt::test::far_sphere_rays(1e4, Real(0.99), 5000, [&](const Ray& r, const Vec3& c) {
        long double ref_near = 0, ref_far = 0;
        REQUIRE(rt::test::reference_roots(r, c, 1, ref_near, ref_far));
        Real tn, tf;
        if (sphere_roots_textbook(r, c, 1, tn, tf))
            worst_textbook = std::max(worst_textbook, rt::test::rel_error(tn, ref_near));
        else
            ++textbook_misses;
        REQUIRE(sphere_roots(r, c, 1, tn, tf));
        worst_stable = std::max(worst_stable, rt::test::rel_error(tn, ref_near));
    });
    const Real eps = rt::test::kEps;
    MESSAGE("Real=" << std::string(real_name()) << ": textbook worst " << worst_textbook / eps << " eps, "
                    << textbook_misses << " false misses; stable worst " << worst_stable / eps << " eps");
    CHECK((textbook_misses > 0 || worst_textbook > 100 * std::max(worst_stable, eps)));
}
