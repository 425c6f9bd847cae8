// Chapter 13: constructive solid geometry (course §9.10). The interval algebra on hand-made
// lists (13.1), touching spans of one list among them; a closed mesh's crossings grouped
// into spans (13.2); each operation against point membership (inside tests of the operands that do not
// use the span code) along random rays; a closed mesh's crossings at shared edges; the lens
// against the thick-lens formula; the thin-span tolerance with a test that fails without it;
// shadows through a die and a block with a hole; operands that are not solids refused; and
// the chapter's scenes the same with every acceleration structure as with brute force.
#include "geometry/limits.hpp"
#include "geometry/procedural.hpp"
#include "geometry/shape.hpp"
#include "io/scene_file.hpp"
#include "shading/optics.hpp"
#include "support.hpp"
#include "support/accel_check.hpp"
#include "support/source_dir.hpp"
#include "support/span_check.hpp"

#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <vector>

using namespace rt;
using rt::test::kEps;
using rt::test::Pairs;
using rt::test::share;
using rt::test::ts;

namespace {

const std::string kScenes = rt::test::source_dir() + "/chapters/ch13_csg/scenes/";

}  // namespace

TEST_CASE("13.1 combine: empty lists, touching, nested and identical spans") {
    const SpanList none;
    const SpanList a = rt::test::span_list({{0, 2}}, 0);
    for (CsgOp op : {CsgOp::union_of, CsgOp::intersection, CsgOp::difference}) {
        CAPTURE(kCsgOpNames[op]);
        CHECK(combine(op, none, none).empty());
        CHECK(combine(op, none, a).size() == (op == CsgOp::union_of ? 1u : 0u));
        CHECK(combine(op, a, none).size() == (op == CsgOp::intersection ? 0u : 1u));
    }

    // Touching: [0, 2] and [2, 4] are one solid in a union, meet in no volume, and the
    // difference keeps the first whole.
    const SpanList b = rt::test::span_list({{2, 4}}, 1);
    CHECK(ts(combine(CsgOp::union_of, a, b)) == Pairs{{0, 4}});
    const SpanList touch = combine(CsgOp::intersection, a, b);
    // No thickness: combine may leave the span for drop_thin, or drop it itself.
    CHECK((touch.empty() || ts(touch) == Pairs{{2, 2}}));
    SpanList dropped = touch;
    drop_thin(dropped, Real(1e-9), Vec3(1, 0, 0));
    CHECK(dropped.empty());
    CHECK(ts(combine(CsgOp::difference, a, b)) == Pairs{{0, 2}});

    // Nested: two spans of b inside one of c.
    const SpanList c = rt::test::span_list({{0, 10}}, 0);
    const SpanList holes = rt::test::span_list({{2, 3}, {5, 6}}, 1);
    CHECK(ts(combine(CsgOp::union_of, c, holes)) == Pairs{{0, 10}});
    CHECK(ts(combine(CsgOp::intersection, c, holes)) == Pairs{{2, 3}, {5, 6}});
    const SpanList cut = combine(CsgOp::difference, c, holes);
    REQUIRE(ts(cut) == Pairs{{0, 2}, {3, 5}, {6, 10}});
    // The result's ends are the operands' records: [3, 5] runs from where the ray leaves the
    // first hole (b's end 1) to where it enters the second (b's end 2).
    CHECK(cut[0].in.primitive == 0);
    CHECK(cut[0].out.primitive == 100);
    CHECK(cut[1].in.primitive == 101);
    CHECK(cut[1].out.primitive == 102);
    CHECK(cut[2].out.primitive == 1);
    CHECK(combine(CsgOp::difference, holes, c).empty());

    // Identical operands. At one t, an end of a or the same end of b may come first: either
    // record will do, so long as it is an end of the right kind at that t.
    const SpanList same = rt::test::span_list({{1, 2}}, 1);
    const SpanList one = rt::test::span_list({{1, 2}}, 0);
    for (CsgOp op : {CsgOp::union_of, CsgOp::intersection}) {
        CAPTURE(kCsgOpNames[op]);
        const SpanList both = combine(op, one, same);
        REQUIRE(ts(both) == Pairs{{1, 2}});
        CHECK((both[0].in.primitive == 0 || both[0].in.primitive == 100));
        CHECK((both[0].out.primitive == 1 || both[0].out.primitive == 101));
    }
    SpanList nothing = combine(CsgOp::difference, one, same);
    drop_thin(nothing, Real(1e-9), Vec3(1, 0, 0));
    CHECK(nothing.empty());

    // Overlapping, several spans each side.
    const SpanList p = rt::test::span_list({{0, 3}, {5, 8}}, 0), q = rt::test::span_list({{1, 6}, {7, 9}}, 1);
    CHECK(ts(combine(CsgOp::union_of, p, q)) == Pairs{{0, 9}});
    CHECK(ts(combine(CsgOp::intersection, p, q)) == Pairs{{1, 3}, {5, 6}, {7, 8}});
    CHECK(ts(combine(CsgOp::difference, p, q)) == Pairs{{0, 1}, {6, 7}});
    CHECK(ts(combine(CsgOp::difference, q, p)) == Pairs{{3, 5}, {8, 9}});
}

TEST_CASE("13.1 combine: spans of one list that touch, counted, not flagged") {
    // a is two spans that touch at t = 2, as a list may hold (a solid cut in two by a face
    // of another, thin 0); b lies across the join. At t = 2 the ray enters a's second span
    // before it leaves the first (entries first), so a count of how deep it is inside a
    // goes 1, 2, 1: it never leaves a. A flag would be set twice and cleared once, and would
    // say the ray is outside a from t = 2 on (book §13.2).
    const SpanList a = rt::test::span_list({{0, 2}, {2, 4}}, 0), b = rt::test::span_list({{1, 3}}, 1);
    CHECK(ts(combine(CsgOp::union_of, a, b)) == Pairs{{0, 4}});
    CHECK(ts(combine(CsgOp::intersection, a, b)) == Pairs{{1, 3}});
    CHECK(ts(combine(CsgOp::difference, a, b)) == Pairs{{0, 1}, {3, 4}});
    CHECK(combine(CsgOp::difference, b, a).empty());
    // And alone: a union with nothing is a itself, one solid.
    CHECK(ts(combine(CsgOp::union_of, a, SpanList{})) == Pairs{{0, 4}});
    // The records: the union runs from where the ray enters a to where it leaves a's second span.
    const SpanList u = combine(CsgOp::union_of, a, b);
    REQUIRE(u.size() == 1);
    CHECK(u[0].in.primitive == 0);
    CHECK(u[0].out.primitive == 3);
}

TEST_CASE("13.2 mesh_spans: crossings grouped at one t, silhouettes, strays") {
    const Vec3 d(0, 0, -1);
    std::uint32_t next = 0;  // each crossing a triangle of its own, to tell the records apart
    auto cross = [&next](Real t, Real nz) {
        HitRecord r;
        r.t = t;
        r.normal = Vec3(0, 0, nz);
        r.primitive = next++;
        return r;
    };
    // Entering through an edge (two front faces, t differing by rounding), leaving through a face.
    CHECK(ts(mesh_spans({cross(1, 1), cross(1 + Real(1e-12), 1), cross(3, -1)}, d, Real(1e-9))) == Pairs{{1, 3}});
    // A silhouette edge (one front face, one back face at the same t) is no crossing.
    CHECK(mesh_spans({cross(2, 1), cross(2, -1)}, d, Real(1e-9)).empty());
    // Two bodies in a row.
    CHECK(ts(mesh_spans({cross(1, 1), cross(2, -1), cross(4, 1), cross(5, -1)}, d, 0)) == Pairs{{1, 2}, {4, 5}});
    // The span's ends are an entering and a leaving record, whatever order a group came in:
    // the first entering crossing of the group that opens it, the first leaving one of the
    // group that closes it (in the crossings' order, by t and then triangle: the one a search
    // for the closest hit returns).
    next = 0;
    const SpanList s =
        mesh_spans({cross(1, -1), cross(1, 1), cross(1, 1), cross(3, 1), cross(3, -1), cross(3, -1)}, d, 0);
    REQUIRE(s.size() == 1);
    CHECK(s[0].in.normal.z == 1);
    CHECK(s[0].out.normal.z == -1);
    CHECK(s[0].in.primitive == 1);
    CHECK(s[0].out.primitive == 4);
    next = 0;
    const SpanList late = mesh_spans({cross(1, 1), cross(3, -1), cross(3 + Real(1e-12), -1)}, d, Real(1e-9));
    REQUIRE(ts(late) == Pairs{{1, 3}});
    CHECK(late[0].out.primitive == 1);
    // "At most same_t" includes equal: with same_t 0, a silhouette at one t is still one
    // group of no crossing, whichever of its two faces comes first.
    CHECK(mesh_spans({cross(2, 1), cross(2, -1)}, d, 0).empty());
    CHECK(mesh_spans({cross(2, -1), cross(2, 1)}, d, 0).empty());
    // A stray leaving crossing outside, or a second entry inside, does not shift the count.
    CHECK(ts(mesh_spans({cross(0, -1), cross(1, 1), cross(2, 1), cross(3, -1)}, d, 0)) == Pairs{{1, 3}});
    CHECK(mesh_spans({}, d, 0).empty());
}

namespace {

// The winding number of a closed mesh around p: the solid angles of its triangles seen from
// p (Van Oosterom and Strackee's formula), over 4 pi. 1 inside, 0 outside, whatever its shape.
Real winding_number(const MeshData& d, const Vec3& p) {
    double sum = 0;
    for (const auto& t : d.triangles) {
        const glm::dvec3 a = glm::dvec3(d.positions[t[0]] - p), b = glm::dvec3(d.positions[t[1]] - p),
                         c = glm::dvec3(d.positions[t[2]] - p);
        const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
        const double num = glm::dot(a, glm::cross(b, c));
        const double den = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
        sum += 2 * std::atan2(num, den);
    }
    return Real(sum / (4 * std::numbers::pi));
}

// Inside tests of the operands that do not use the span code: the sphere's distance, the
// box's slabs, a convex mesh's face planes, an instance's inverse, and the operation itself.
bool inside(const Shape& shape, const Vec3& p) {
    if (const auto* s = std::get_if<Sphere>(&shape)) return glm::length(p - s->center) < s->radius;
    if (const auto* b = std::get_if<Cuboid>(&shape))
        return glm::all(glm::lessThan(b->min, p)) && glm::all(glm::lessThan(p, b->max));
    if (const auto* m = std::get_if<Mesh>(&shape)) {
        const MeshData& d = m->data();
        if (d.triangles.size() <= 64) return winding_number(d, p) > Real(0.5);  // any closed mesh
        // Convex (the icosphere): behind every face, and far cheaper than the winding number.
        for (const auto& t : d.triangles) {
            const Vec3 a = d.positions[t[0]];
            const Vec3 n = glm::cross(d.positions[t[1]] - a, d.positions[t[2]] - a);
            if (glm::dot(n, p - a) >= 0) return false;
        }
        return true;
    }
    if (const auto* in = std::get_if<Instance>(&shape)) return inside(in->base(), in->to_object().point(p));
    if (const auto* c = std::get_if<Csg>(&shape)) {
        const bool a = inside(*c->left().shape, p), b = inside(*c->right().shape, p);
        return c->op() == CsgOp::union_of ? a || b : c->op() == CsgOp::intersection ? a && b : a && !b;
    }
    return false;
}

// Samples the ray's line between the ends of the spans and past them, away from every end,
// and counts the points whose inside test disagrees with the spans.
int membership_errors(const Shape& shape, const Ray& ray) {
    SpanList s;
    spans(shape, ray, s);
    std::vector<Real> ends;
    for (const Span& x : s) {
        CHECK(x.in.t <= x.out.t);
        ends.push_back(x.in.t);
        ends.push_back(x.out.t);
    }
    for (std::size_t k = 1; k < ends.size(); ++k) CHECK(ends[k - 1] <= ends[k]);
    std::vector<Real> samples;
    const Real far = ends.empty() ? 0 : std::max(std::abs(ends.front()), std::abs(ends.back())) + 1;
    samples.push_back(ends.empty() ? 0 : ends.front() - 0.5f);
    for (std::size_t k = 1; k < ends.size(); ++k)
        if (ends[k] - ends[k - 1] > Real(1e-4)) samples.push_back((ends[k - 1] + ends[k]) / 2);
    if (!ends.empty()) samples.push_back(ends.back() + 0.5f);
    samples.push_back(-far);
    // And along the line wherever no end is near (not at t = 1: the edge tests aim there).
    for (int k = -4; k <= 8; ++k) {
        const Real t = Real(k) / 2 + Real(0.1234567);
        bool near = false;
        for (Real e : ends) near |= std::abs(e - t) < Real(1e-4);
        if (!near) samples.push_back(t);
    }
    int errors = 0;
    for (Real t : samples) {
        bool in_span = false;
        for (const Span& x : s) in_span |= x.in.t < t && t < x.out.t;
        if (in_span != inside(shape, ray.at(t))) ++errors;
    }
    return errors;
}

// Operands of every kind: spheres, a turned box, a closed (convex) mesh, and a CSG object
// under an instance.
std::vector<std::shared_ptr<const Shape>> solids() {
    std::vector<std::shared_ptr<const Shape>> s;
    s.push_back(share(Sphere(Vec3(0.3, 0, 0), 1)));
    s.push_back(share(Instance(share(Cuboid(Vec3(-0.8, -0.6, -0.7), Vec3(0.7, 0.9, 0.6))),
                               Affine::rotate(Vec3(1, 2, 3), 35).then(Affine::translate(Vec3(-0.2, 0.1, 0))))));
    s.push_back(share(Mesh(icosphere(Vec3(0, 0.4, 0.2), Real(0.9), 2))));
    s.push_back(share(Mesh(subdivided_cube(Vec3(0.4, -0.3, 0.1), Real(1.1), 2))));
    const auto inner = share(Csg(CsgOp::difference, CsgOperand{share(Sphere(Vec3(0), Real(1.1)))},
                                 CsgOperand{share(Cuboid(Vec3(-2, -0.3, -0.3), Vec3(2, 0.3, 0.3)))}));
    s.push_back(share(Instance(inner, Affine::rotate(Vec3(0, 1, 1), 50).then(Affine::translate(Vec3(0, 0, 0.3))))));
    return s;
}

}  // namespace

TEST_CASE("every operation agrees with point membership along random rays") {
    const auto operands = solids();
    rt::test::Rng rng;
    for (CsgOp op : {CsgOp::union_of, CsgOp::intersection, CsgOp::difference})
        for (std::size_t i = 0; i < operands.size(); ++i)
            for (std::size_t j = 0; j < operands.size(); ++j) {
                if (i == j) continue;
                const Shape csg = Csg(op, CsgOperand{operands[i]}, CsgOperand{operands[j]});
                // Nested once more: the result minus a small ball.
                const Shape deeper = Csg(CsgOp::difference, CsgOperand{share(csg)},
                                         CsgOperand{share(Sphere(Vec3(0.2, 0.5, 0.1), Real(0.35)))});
                int errors = 0;
                for (int k = 0; k < 300; ++k) {
                    const Vec3 o = rng.vec(-4, 4), target = rng.vec(-1, 1);
                    const Ray ray{o, target - o};
                    errors += membership_errors(csg, ray) + membership_errors(deeper, ray);
                }
                CAPTURE(kCsgOpNames[op]);
                CAPTURE(i);
                CAPTURE(j);
                CHECK(errors == 0);
            }
}

TEST_CASE("a concave closed mesh: several spans per ray, each operation against point membership") {
    // A cube whose +x face has its middle vertex pushed 0.44 inwards: a pyramid-shaped dent,
    // so a ray across the dent leaves and enters the mesh again. Judged by the winding number.
    MeshData dented = subdivided_cube(Vec3(0), Real(1.1), 2);
    int moved = 0;
    for (Vec3& v : dented.positions)
        if (v.x > Real(0.5) && std::abs(v.y) < Real(0.01) && std::abs(v.z) < Real(0.01)) {
            v.x -= Real(0.44);
            ++moved;
        }
    REQUIRE(moved == 1);
    const auto mesh = share(Mesh(dented));
    CHECK(not_solid(*mesh).empty());
    SpanList twice;
    spans(*mesh, Ray{Vec3(0.3, Real(0.05), -3), Vec3(0, 0, 1)}, twice);  // through the dent
    CHECK(twice.size() == 2);
    rt::test::Rng rng;
    const auto ball = share(Sphere(Vec3(0.6, 0.1, 0), Real(0.5)));
    const auto bar = share(Cuboid(Vec3(-2, -0.2, -0.2), Vec3(2, 0.2, 0.2)));
    int errors = 0;
    for (CsgOp op : {CsgOp::union_of, CsgOp::intersection, CsgOp::difference})
        for (const auto& other : {ball, bar})
            for (int k = 0; k < 300; ++k) {
                const Vec3 o = rng.vec(-4, 4), target = rng.vec(-0.8, 0.8);
                const Ray ray{o, target - o};
                errors += membership_errors(*mesh, ray) + membership_errors(Csg(op, {mesh}, {other}), ray) +
                          membership_errors(Csg(op, {other}, {mesh}), ray);
            }
    CHECK(errors == 0);
}

TEST_CASE("13.2 a closed mesh's spans at shared edges and vertices: those of its inside") {
    const MeshData ball = icosphere(Vec3(0), 1, 2);
    const Shape mesh = Mesh(ball);
    rt::test::RaySet all, crossing;
    rt::test::edge_rays(ball, Vec3(0), all, crossing);
    int errors = 0, missed = 0, grazing = 0;
    for (std::size_t k = 0; k < all.rays.size(); ++k) errors += membership_errors(mesh, all.rays[k]);
    for (const Ray& ray : crossing.rays) {  // aimed through an edge or vertex: one span, entered there
        SpanList s;
        spans(mesh, ray, s);
        // Where the ray passes from outside to inside at t = 1 (or back), a span starts (or
        // ends) there. Some rays only graze a vertex or an edge there: no end of a span.
        const bool before = inside(mesh, ray.at(Real(0.999))), after = inside(mesh, ray.at(Real(1.001)));
        bool starts = false, ends = false;
        for (const Span& x : s) {
            starts |= std::abs(x.in.t - 1) <= 1e3 * kEps;
            ends |= std::abs(x.out.t - 1) <= 1e3 * kEps;
        }
        const bool enters = !before && after;
        const bool bad = (enters && !starts) || (before && !after && !ends) || (before == after && (starts || ends));
        if (bad && missed == 0) {  // the first, in full
            CAPTURE(before);
            CAPTURE(after);
            CAPTURE(s.size());
            CAPTURE(ray.origin);
            CAPTURE(ray.direction);
            for (const Span& x : s) MESSAGE(double(x.in.t) << " .. " << double(x.out.t));
            CHECK_FALSE(bad);
        }
        missed += bad;
        grazing += before == after;
    }
    CHECK(all.rays.size() > 400);
    CHECK(errors == 0);
    CHECK(missed == 0);
    CHECK(grazing < int(crossing.rays.size()) / 50);
}

TEST_CASE("the lens: both hit distances of an axial ray, and its focus against the thick-lens formula") {
    // Two spheres of radius R with centres D apart on the z axis: the lens between them is
    // 2R - D thick, its faces at z = +-(R - D/2).
    const Real R = 2, D = Real(3.4), n = Real(1.5);
    const Shape lens = Csg(CsgOp::intersection, CsgOperand{share(Sphere(Vec3(0, 0, -D / 2), R))},
                           CsgOperand{share(Sphere(Vec3(0, 0, D / 2), R))});
    const Real face = R - D / 2;
    const Ray axial{Vec3(0, 0, 10), Vec3(0, 0, -1)};
    SpanList s;
    spans(lens, axial, s);
    REQUIRE(s.size() == 1);
    CHECK(std::abs(s[0].in.t - (10 - face)) <= 16 * kEps * 10);
    CHECK(std::abs(s[0].out.t - (10 + face)) <= 16 * kEps * 10);
    CHECK(s[0].in.normal == Vec3(0, 0, 1));  // the front face's outward normal
    HitRecord rec;
    REQUIRE(hit_record(lens, axial, Interval{0, kInfinity}, SurfaceRef{}, rec));
    CHECK(rec.t == s[0].in.t);
    // Starting inside the glass, the first end is where the ray leaves.
    REQUIRE(hit_record(lens, Ray{Vec3(0, 0, 0), Vec3(0, 0, -1)}, Interval{0, kInfinity}, SurfaceRef{}, rec));
    CHECK(std::abs(rec.t - face) <= 16 * kEps);
    CHECK(rec.normal.z < 0);

    // A ray parallel to the axis at height h, refracted in and out by Snell's law, crosses
    // the axis at the back focal distance of a thick lens with R1 = R2 = R, thickness d:
    //   1/f = (n - 1) (2/R - (n - 1) d / (n R^2)),  BFD = f (1 - (n - 1) d / (n R)).
    const Real d = 2 * face;
    const Real f = 1 / ((n - 1) * (2 / R - (n - 1) * d / (n * R * R)));
    const Real bfd = f * (1 - (n - 1) * d / (n * R));
    const Real h = Real(0.01);  // paraxial: the spherical aberration is of order (h/R)^2
    Ray ray{Vec3(0, h, 10), Vec3(0, 0, -1)};
    REQUIRE(hit_record(lens, ray, Interval{0, kInfinity}, SurfaceRef{}, rec));
    Vec3 inside_dir;
    REQUIRE(refract(ray.direction, rec.normal, 1, n, inside_dir));
    ray = Ray{rec.p, inside_dir};
    REQUIRE(hit_record(lens, ray, Interval{Real(1e-6), kInfinity}, SurfaceRef{}, rec));
    Vec3 out_dir;
    REQUIRE(refract(ray.direction, -rec.normal, n, 1, out_dir));
    const Real to_axis = -rec.p.y / out_dir.y;
    const Real focus_z = rec.p.z + to_axis * out_dir.z;
    CHECK(out_dir.y < 0);  // bent towards the axis
    CHECK(std::abs((-face - focus_z) - bfd) < Real(2e-3) * bfd);

    // Unequal radii, so that mixing them up fails: a sphere of radius R1 = 3 centred at
    // z = -2.5 (its surface at z = 0.5 on the axis) and one of R2 = 1.5 centred at z = 1 (at
    // z = -0.5): the axial ray enters at z = 0.5 and leaves at z = -0.5; a ray parallel to
    // the axis at height 0.6 meets the faces where z = -2.5 + sqrt(9 - 0.36) and
    // z = 1 - sqrt(2.25 - 0.36).
    const Shape uneven = Csg(CsgOp::intersection, CsgOperand{share(Sphere(Vec3(0, 0, Real(-2.5)), 3))},
                             CsgOperand{share(Sphere(Vec3(0, 0, 1), Real(1.5)))});
    SpanList u;
    spans(uneven, axial, u);
    REQUIRE(u.size() == 1);
    CHECK(std::abs(u[0].in.t - Real(9.5)) <= 16 * kEps * 10);
    CHECK(std::abs(u[0].out.t - Real(10.5)) <= 16 * kEps * 10);
    spans(uneven, Ray{Vec3(0, Real(0.6), 10), Vec3(0, 0, -1)}, u);
    REQUIRE(u.size() == 1);
    CHECK(std::abs(u[0].in.t - (10 - (std::sqrt(Real(8.64)) - Real(2.5)))) <= 64 * kEps * 10);
    CHECK(std::abs(u[0].out.t - (10 - (1 - std::sqrt(Real(1.89))))) <= 64 * kEps * 10);
}

TEST_CASE("bounding boxes: union, intersection, difference; and every hit inside its box") {
    const auto a = share(Sphere(Vec3(0), 1)), b = share(Cuboid(Vec3(0.5, -0.5, -0.5), Vec3(3, 0.5, 0.5)));
    const Box u = bounding_box(Csg(CsgOp::union_of, {a}, {b}));
    CHECK(u.min == Vec3(-1, -1, -1));
    CHECK(u.max == Vec3(3, 1, 1));
    const Box i = bounding_box(Csg(CsgOp::intersection, {a}, {b}));
    CHECK(i.min == Vec3(0.5, -0.5, -0.5));
    CHECK(i.max == Vec3(1, 0.5, 0.5));
    const Box d = bounding_box(Csg(CsgOp::difference, {a}, {b}));
    CHECK(d.min == Vec3(-1));
    CHECK(d.max == Vec3(1));
    CHECK_THROWS_WITH_AS(Csg(CsgOp::intersection, {a}, {share(Sphere(Vec3(5, 0, 0), 1))}),
                         doctest::Contains("intersection is empty"), std::invalid_argument);
    // The boxes are tight enough for a BVH and still hold every hit point.
    rt::test::Rng rng;
    int outside = 0;
    for (const Shape& s : {Shape(Csg(CsgOp::intersection, {a}, {b})), Shape(Csg(CsgOp::difference, {a}, {b}))}) {
        const Box box = bounding_box(s);
        for (int k = 0; k < 2000; ++k) {
            const Vec3 o = rng.vec(-3, 3);
            HitRecord rec;
            if (!hit_record(s, Ray{o, rng.vec(-1, 1) - o}, Interval{}, SurfaceRef{}, rec)) continue;
            const Real slack = 1e3 * kEps;
            outside +=
                glm::any(glm::lessThan(rec.p, box.min - slack)) || glm::any(glm::greaterThan(rec.p, box.max + slack));
        }
    }
    CHECK(outside == 0);
}

TEST_CASE("operands: their material and normal, flipped when subtracted; --pick names them") {
    const auto block = share(Cuboid(Vec3(-1), Vec3(1)));
    const auto pip = share(Sphere(Vec3(0, 1, 0), Real(0.3)));
    const Csg die(CsgOp::difference, CsgOperand{block, 4, "body"}, CsgOperand{pip, 7, "pip"});
    HitRecord rec;
    // Straight down into the pip: the ray meets the pip's bottom, inside the block.
    REQUIRE(hit_record(Shape(die), Ray{Vec3(0, 3, 0), Vec3(0, -1, 0)}, Interval{}, SurfaceRef{2, 9}, rec));
    CHECK(std::abs(rec.t - Real(2.3)) < 16 * kEps);
    CHECK(rec.normal.y > Real(0.999));  // the sphere's outward normal there is -y; flipped
    CHECK(rec.material == 7);
    CHECK(rec.surface == 2);
    CHECK(die.describe(rec.part) == "pip (sphere), subtracted");
    // Beside the pip: the block's top face, the block's material.
    REQUIRE(hit_record(Shape(die), Ray{Vec3(0.6, 3, 0), Vec3(0, -1, 0)}, Interval{}, SurfaceRef{2, 9}, rec));
    CHECK(rec.t == 2);
    CHECK(rec.normal == Vec3(0, 1, 0));
    CHECK(rec.material == 4);
    CHECK(die.describe(rec.part) == "body (box)");
    // An operand without a material takes the surface's.
    const Csg plain(CsgOp::union_of, CsgOperand{block}, CsgOperand{pip});
    REQUIRE(hit_record(Shape(plain), Ray{Vec3(0.6, 3, 0), Vec3(0, -1, 0)}, Interval{}, SurfaceRef{2, 9}, rec));
    CHECK(rec.material == 9);
    // Nested and instanced: parts numbered left to right through the whole tree.
    const auto inner = share(Instance(share(die), Affine::translate(Vec3(0, 0, 0))));
    const Csg outer(CsgOp::union_of, CsgOperand{share(Sphere(Vec3(5, 0, 0), 1)), kNone, "moon"}, CsgOperand{inner});
    CHECK(outer.leaves() == 3);
    CHECK(outer.describe(0) == "moon (sphere)");
    CHECK(outer.describe(2) == "pip (sphere), subtracted");
    REQUIRE(hit_record(Shape(outer), Ray{Vec3(0, 3, 0), Vec3(0, -1, 0)}, Interval{}, SurfaceRef{}, rec));
    CHECK(rec.part == 2);
}

TEST_CASE("shadows: a die casts the rounded cube's shadow, a block with a hole lets light through") {
    SceneSummary summary;
    const Scene die = load_scene_file(kScenes + "die.json", &summary);
    const Csg* csg = nullptr;
    for (const Surface& s : die.surfaces.surfaces())
        if (const auto* in = std::get_if<Instance>(&s.shape))
            if (const auto* c = std::get_if<Csg>(&in->base())) csg = c;
    REQUIRE(csg != nullptr);
    CHECK(csg->leaves() == 23);  // cube, rounding sphere, 21 pips
    // Straight down from above: blocked over the die's footprint (pips only dent its top),
    // lit beside it.
    const Shape shape = Csg(*csg);
    int wrong = 0;
    for (int i = -10; i <= 10; ++i)
        for (int j = -10; j <= 10; ++j) {
            const Vec3 p(Real(i) * Real(0.06), 5, Real(j) * Real(0.06));
            const Ray down{p, Vec3(0, -1, 0)};
            // The rounded cube is the cube [-0.5, 0.5]^3 cut by a ball of radius 0.75: seen from
            // above (its widest section is at y = 0), the square cut by a disk of radius 0.75.
            const Real r2 = p.x * p.x + p.z * p.z;
            const bool shadow = std::abs(p.x) < Real(0.5) && std::abs(p.z) < Real(0.5) && r2 < Real(0.5624);
            const bool lit = std::abs(p.x) > Real(0.5) || std::abs(p.z) > Real(0.5) || r2 > Real(0.5626);
            const bool blocked = occluded(shape, down, Interval{0, kInfinity});
            wrong += (shadow && !blocked) || (lit && blocked);
        }
    CHECK(wrong == 0);
    // Along the diagonal (1, 1, 1) the shadow is no simple figure: the cube's outline is a
    // hexagon reaching 0.816 from the axis, past the ball's 0.75, and the pips dent the
    // edges. Each line is judged by the inside tests of its points instead: blocked where 5
    // or more of its points 0.002 apart are inside the die, lit where none is (grazing lines,
    // with 1 to 4, are left out).
    const Vec3 d = glm::normalize(Vec3(1, 1, 1));
    const Vec3 e1 = glm::normalize(Vec3(1, -1, 0)), e2 = glm::cross(d, e1);
    int judged_blocked = 0, judged_lit = 0, diagonal_wrong = 0;
    for (int i = -22; i <= 22; ++i)
        for (int j = -22; j <= 22; ++j) {
            const Vec3 o = Real(i) * Real(0.04) * e1 + Real(j) * Real(0.04) * e2 - Real(2) * d;
            int in = 0;
            for (int k = 0; k <= 2000; ++k) in += inside(shape, o + Real(k) * Real(0.002) * d);
            if (in >= 1 && in <= 4) continue;
            const bool blocked = occluded(shape, Ray{o, d}, Interval{0, kInfinity});
            (in ? judged_blocked : judged_lit) += 1;
            diagonal_wrong += blocked != (in > 0);
        }
    CHECK(judged_blocked > 500);
    CHECK(judged_lit > 500);
    CHECK(diagonal_wrong == 0);

    const Shape holed = Csg(CsgOp::difference, CsgOperand{share(Cuboid(Vec3(-1), Vec3(1)))},
                            CsgOperand{share(Cuboid(Vec3(-0.3, -2, -0.3), Vec3(0.3, 2, 0.3)))});
    CHECK_FALSE(occluded(holed, Ray{Vec3(0.1, 5, 0), Vec3(0, -1, 0)}, Interval{0, kInfinity}));
    CHECK(occluded(holed, Ray{Vec3(0.5, 5, 0), Vec3(0, -1, 0)}, Interval{0, kInfinity}));
    // A segment that ends inside the hole is not blocked by the hole's walls.
    CHECK_FALSE(occluded(holed, Ray{Vec3(0, 5, 0), Vec3(0, -1, 0)}, Interval{0, 4}));
}

TEST_CASE("the thin tolerance: coplanar faces met through two transforms leave slivers without it") {
    // The coplanar scene's slab and hole, far from the origin and near it: straight down
    // through the hole's middle the ray must meet nothing of the slab.
    for (const Vec3 offset : {Vec3(0), Vec3(3000, -2000, 1000)}) {
        const auto slab = share(Instance(share(Cuboid(Vec3(-1.2, 0.3, -1.2), Vec3(1.2, 0.7, 1.2))),
                                         Affine::rotate(Vec3(0, 1, 0), 30).then(Affine::translate(offset))));
        const auto hole =
            share(Instance(share(Cuboid(Vec3(-1), Vec3(1))), Affine::scale(Vec3(0.55, 0.2, 0.55))
                                                                 .then(Affine::translate(Vec3(0.1, 0.5, 0)))
                                                                 .then(Affine::rotate(Vec3(0, 1, 0), 30))
                                                                 .then(Affine::translate(offset))));
        const Shape with = Csg(CsgOp::difference, {slab}, {hole});
        const Shape without = Csg(CsgOp::difference, {slab}, {hole}, 0);
        const Affine turn = Affine::rotate(Vec3(0, 1, 0), 30);
        int slivers_with = 0, slivers_without = 0;
        for (int i = 0; i < 40; ++i)
            for (int j = 0; j < 40; ++j) {
                // A point well inside the hole's square (side 1.1, centre (0.1, 0)), turned.
                const Vec3 local(Real(0.1) + Real(-0.45 + 0.9 * i / 39.0), 0, Real(-0.45 + 0.9 * j / 39.0));
                const Vec3 p = turn.point(local) + offset + Vec3(0, 0.5, 0);
                const Ray ray{p + Vec3(0.3, 3, 0.2), -Vec3(0.3, 3, 0.2)};
                slivers_with += occluded(with, ray, Interval{0, Real(0.99)});
                slivers_without += occluded(without, ray, Interval{0, Real(0.99)});
            }
        CAPTURE(offset);
        CHECK(slivers_with == 0);
        CHECK(slivers_without > 0);  // the test can fail: thin 0 keeps them
    }
}

TEST_CASE("the chapter's scenes: the same image with every structure as with brute force") {
    for (const char* name : {"lens", "die", "nested", "meshes", "coplanar"}) {
        CAPTURE(name);
        const Scene scene = load_scene_file(kScenes + std::string(name) + ".json");
        CHECK(rt::test::image_differences(scene, rt::kAccelKinds) == 0);
    }
}

TEST_CASE("far from the origin, out to the coordinate limit: the same image with every structure as with brute force") {
    // A floor with balls, a triangle and a box on it, moved far out and seen from close by,
    // from above and at grazing angles. Float's step there (1/16 at 1e6, 8 at 1e8) is far
    // above the pads that suit a scene near the origin: a flat scene's added thickness
    // vanished (the grid's cells became infinite) and hits on a wall in the box's face
    // rounded outside it (the BSPs lost them). Whatever rounding makes of the hits, every
    // structure must find the same ones as brute force (the BVHs lost a few in float: a ray
    // that missed a node's box by a rounding error while the floor's own test rounded to a
    // hit, until their boxes grew by that rounding, core/hit_rounding.hpp's grown_by_rounding).
    const auto scene_at = [](const Vec3& o, double size, const Vec3& eye) {
        const auto at = [&](double x, double y, double z) {
            return std::string("[") + std::to_string(double(o.x) + x * size) + ", " +
                   std::to_string(double(o.y) + y * size) + ", " + std::to_string(double(o.z) + z * size) + "]";
        };
        const std::string ball = R"(, {"type": "sphere", "material": "m", "radius": )" + std::to_string(size) + ", ";
        return R"({"camera": {"eye": )" + at(eye.x, eye.y, eye.z) + R"(, "target": )" + at(0, 0, 0) +
               R"(, "fov": 60}, "background": [0.6, 0.7, 0.85],
            "materials": {"m": {"diffuse": [0.8, 0.3, 0.2]},
                          "floor": {"diffuse": [0.9, 0.9, 0.85], "checker": [0.2, 0.25, 0.3], "checker_size": )" +
               std::to_string(size / 4) + R"(}},
            "lights": [{"type": "point", "position": )" +
               at(0, 10, 4) + R"(, "color": [0.8, 0.8, 0.8]}],
            "surfaces": [{"type": "polygon", "material": "floor", "vertices": [)" +
               at(-8, 0, -8) + ", " + at(-8, 0, 8) + ", " + at(8, 0, 8) + ", " + at(8, 0, -8) + "]}" + ball +
               R"("center": )" + at(0, 1, 0) + "}" + ball + R"("center": )" + at(3, 1, -2) + "}" +
               R"(, {"type": "triangle", "material": "m", "vertices": [)" + at(-5, 0, 2) + ", " + at(-3, 0, 2) + ", " +
               at(-4, 3, 2) + R"(]}, {"type": "box", "material": "m", "min": )" + at(2, 0, 2) + R"(, "max": )" +
               at(4, 2, 4) + "}]}";
    };
    const Vec3 eyes[] = {Vec3(0, 10, 20), Vec3(20, 1, 20), Vec3(-10, 3, -15), Vec3(0, 0.5, 12)};
    struct Place {
        Vec3 origin;
        double size;
    };
    const double edge = limits::coordinate.max;
    for (const Place& place : {Place{Vec3(1e6, -2e6, 3e6), 1}, Place{Vec3(-edge + 250, edge - 250, edge - 250), 10},
                               Place{Vec3(edge - 250, -edge + 250, -3e7), 10}})
        for (const Vec3& eye : eyes) {
            CAPTURE(place.origin);
            CAPTURE(eye);
            const Scene scene = load_scene_text(scene_at(place.origin, place.size, eye), "far.json", ".");
            CHECK(rt::test::image_differences(scene, rt::kAccelKinds, 48, 36) == 0);
        }
}

TEST_CASE("a long operand list nests as a balanced tree: 1024 balls, the first minus the rest") {
    std::string text = R"({"camera": {"eye": [0, 0, 50], "target": [0, 0, 0]}, "surfaces": [
 {"type": "csg", "op": "difference", "operands": [{"type": "box", "min": [-40, -1, -1], "max": [40, 1, 1]})";
    for (int k = 1; k < 1024; ++k)
        text += R"(, {"type": "sphere", "center": [)" + std::to_string(-40 + 0.078 * k) + R"(, 0, 1], "radius": 0.03})";
    text += "]}]}";
    const Scene scene = load_scene_text(text, "balls.json", ".");
    const auto* csg = std::get_if<Csg>(&scene.surfaces[0].shape);
    REQUIRE(csg != nullptr);
    CHECK(csg->leaves() == 1024);
    // Straight down onto ball 500's centre: the bottom of its pit, 0.03 below the box's top.
    HitRecord rec;
    const Ray down{Vec3(-40 + 0.078 * 500, 0, 5), Vec3(0, 0, -1)};
    REQUIRE(hit_record(scene.surfaces[0].shape, down, Interval{}, SurfaceRef{}, rec));
    CHECK(std::abs(rec.t - Real(4.03)) < 1e3 * kEps);
    CHECK(csg->describe(rec.part) == "sphere, subtracted");
    // Between two pits, the box's top face.
    REQUIRE(hit_record(scene.surfaces[0].shape, Ray{down.origin + Vec3(0.039, 0, 0), down.direction}, Interval{},
                       SurfaceRef{}, rec));
    CHECK(rec.t == 4);
    CHECK(csg->describe(rec.part) == "box");
}
