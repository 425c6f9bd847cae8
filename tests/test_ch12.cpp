// Chapter 12: the BSP tree (course §9.9.4). The four cases of the course's traversal, each
// seen by which leaves a ray visits, and counted against the cases written out here; the
// course's pseudo-code's -0 trap, and -0 with the slack; the cyclic midpoint build, node by
// node, the primitives it lists on both sides of a plane, and its depth limit; the
// surface-area heuristic cutting off empty space; and both builds against brute force on
// random rays, on rays through a closed mesh's shared edges, far from the origin, at walls
// in the tree's box's faces, and on the chapter's scenes. The 12.2 tests of the tree's shape
// run no 12.1; the tests on the library's SAH tree run no 12.2.
#include "accel/accel.hpp"
#include "io/scene_file.hpp"
#include "render/integrators.hpp"
#include "support.hpp"
#include "support/accel_check.hpp"
#include "support/source_dir.hpp"
#include "support/wall_rays.hpp"

#include <algorithm>
#include <cmath>

using namespace rt;
using rt::test::kEps;

namespace {

const std::string kScenes = rt::test::source_dir() + "/chapters/ch12_bsp/scenes/";
constexpr AccelKind kBsps[] = {AccelKind::bsp_midpoint, AccelKind::bsp};

// Two small balls on the x axis, one each side of x = 0, and a triangle in the plane
// z = -1 that crosses x = 0. The midpoint build cuts the cell [-2.3, 2.3] at x = 0 first.
SurfaceList two_balls() {
    SurfaceList list;
    list.add(Sphere(Vec3(-2, 0, 0), Real(0.3)));
    list.add(Sphere(Vec3(2, 0, 0), Real(0.3)));
    list.add(Triangle(Vec3(-1, -1, -1), Vec3(1, -1, -1), Vec3(0, 1, -1)));
    return list;
}

struct Search {
    bool hit = false;
    HitRecord rec;
    std::uint64_t nodes = 0, items = 0;
};

Search search(const Bsp& bsp, const SurfaceList& list, const Ray& ray, Interval interval = {}) {
    Search s;
    traversal_tally = {};
    s.hit = bsp.hit(list, ray, interval, s.rec);
    s.nodes = traversal_tally.nodes;
    s.items = traversal_tally.items;
    return s;
}

// The course's pseudo-code as printed: the side from x_p < D, "moving away" as x_b < 0,
// and the plane's t with no slack. Here only to show what it gets wrong.
bool course_hit_node(const Bsp& bsp, const SurfaceList& list, BspRef ref, const Ray& ray, Real t0, Real t1,
                     HitRecord& best) {
    const BspNode& n = bsp.node(ref);
    if (n.leaf()) return bsp.hit_leaf(list, n, ray, Interval{t0, t1}, best);
    const Real xa = ray.origin[n.axis], xb = ray.direction[n.axis], xp = xa + t0 * xb;
    if (xp < n.split) {
        if (xb < 0) return course_hit_node(bsp, list, n.left, ray, t0, t1, best);
        const Real t = (n.split - xa) / xb;
        if (t > t1) return course_hit_node(bsp, list, n.left, ray, t0, t1, best);
        if (course_hit_node(bsp, list, n.left, ray, t0, t, best)) return true;
        return course_hit_node(bsp, list, n.right, ray, t, t1, best);
    }
    if (xb > 0) return course_hit_node(bsp, list, n.right, ray, t0, t1, best);
    const Real t = (n.split - xa) / xb;
    if (t > t1) return course_hit_node(bsp, list, n.right, ray, t0, t1, best);
    if (course_hit_node(bsp, list, n.right, ray, t0, t, best)) return true;
    return course_hit_node(bsp, list, n.left, ray, t, t1, best);
}

// The four cases as §12.2 states them, to count the nodes and primitives a search should
// visit: exercise 12.1 must visit the same. (The side a part that starts exactly on a plane
// takes is free, since both sides' parts reach the slack past it; the rays these counts are
// taken on never start on one.)
bool four_cases(const Bsp& bsp, const SurfaceList& list, BspRef ref, const Ray& ray, Interval part, HitRecord& best) {
    const BspNode& n = bsp.node(ref);
    if (n.leaf()) return bsp.hit_leaf(list, n, ray, part, best);
    const Real d = ray.direction[n.axis];
    const bool below = ray.origin[n.axis] + part.min * d < n.split;
    const BspRef near = below ? n.left : n.right, far = below ? n.right : n.left;
    const bool towards = below ? d > 0 : d < 0;
    if (!towards) return four_cases(bsp, list, near, ray, part, best);
    const Real t = (n.split - ray.origin[n.axis]) / d, s = bsp.slack(ray, n.axis);
    if (t - s > part.max) return four_cases(bsp, list, near, ray, part, best);
    if (four_cases(bsp, list, near, ray, Interval{part.min, std::min(part.max, t + s)}, best)) return true;
    return four_cases(bsp, list, far, ray, Interval{std::max(part.min, t - s), part.max}, best);
}

// What Bsp::hit does around the search, with four_cases for hit_node.
Search expected(const Bsp& bsp, const SurfaceList& list, const Ray& ray, Interval interval = {}) {
    Search s;
    traversal_tally = {};
    s.rec = no_hit_before(interval.max);
    if (bsp.reach(ray, interval)) s.hit = four_cases(bsp, list, bsp.root(), ray, interval, s.rec);
    s.nodes = traversal_tally.nodes;
    s.items = traversal_tally.items;
    return s;
}

}  // namespace

TEST_SUITE("ch12") {
TEST_CASE("12.2 the midpoint build: x first, then y, then z; a leaf when the list is short") {
    // Four balls at the corners of a square in the xy plane: the root cuts x at the middle,
    // its children cut y, and each leaf holds one ball.
    SurfaceList list;
    for (const Vec3& c : {Vec3(-2, -2, 0), Vec3(2, -2, 0), Vec3(-2, 2, 0), Vec3(2, 2, 0)})
        list.add(Sphere(c, Real(0.5)));
    const Bsp bsp(list, BspBuild::midpoint, 1);
    const BspNode& root = bsp.node(bsp.root());
    REQUIRE_FALSE(root.leaf());
    CHECK(root.axis == 0);
    CHECK(root.split == 0);
    for (BspRef child : {root.left, root.right}) {
        const BspNode& n = bsp.node(child);
        REQUIRE_FALSE(n.leaf());
        CHECK(n.axis == 1);
        CHECK(n.split == 0);
        CHECK(bsp.items(bsp.node(n.left)).size() == 1);
        CHECK(bsp.items(bsp.node(n.right)).size() == 1);
    }
    CHECK(bsp.node_count() == 7);
    CHECK(bsp.entries() == 4);
    CHECK(bsp.depth() == 2);
    // With leaves of up to 4 the four balls are one leaf.
    CHECK(Bsp(list, BspBuild::midpoint, 4).node_count() == 1);
}

TEST_CASE("12.2 a primitive that crosses a plane is listed on both sides") {
    const SurfaceList list = two_balls();
    const Bsp bsp(list, BspBuild::midpoint, 1);
    const BspNode& root = bsp.node(bsp.root());
    REQUIRE(root.axis == 0);
    CHECK(root.split == 0);
    CHECK(bsp.entries() > bsp.primitive_count());
    // The triangle (primitive 2) is under both children.
    const auto holds = [&](BspRef ref, std::uint32_t p) {
        std::vector<BspRef> stack{ref};
        while (!stack.empty()) {
            const BspNode& n = bsp.node(stack.back());
            stack.pop_back();
            if (n.leaf()) {
                const auto it = bsp.items(n);
                if (std::find(it.begin(), it.end(), p) != it.end()) return true;
            } else {
                stack.push_back(n.left);
                stack.push_back(n.right);
            }
        }
        return false;
    };
    CHECK(holds(root.left, 2));
    CHECK(holds(root.right, 2));
    CHECK(holds(root.left, 0));
    CHECK_FALSE(holds(root.right, 0));
    CHECK_FALSE(holds(root.left, 1));
}

TEST_CASE("12.2 a cut that copies more than half the list is skipped; a pile nothing divides is a leaf") {
    const auto rod = [](Real y) { return Triangle(Vec3(-3, y, 0), Vec3(3, y, 0), Vec3(3, y + Real(0.2), 0)); };
    // Three rods along x, stacked in y: every rod crosses x's middle, so the root cuts y.
    SurfaceList rods;
    for (Real y : {Real(-2), Real(0), Real(2)}) rods.add(rod(y));
    const Bsp bsp(rods, BspBuild::midpoint, 1);
    CHECK(bsp.node(bsp.root()).axis == 1);
    // Two rods and two balls: x's middle copies two of four (3 + 3 listed, not more than
    // 1.5 x 4): cut. Three rods and a ball: it would copy three (3 + 4 listed): y instead.
    SurfaceList half;
    half.add(rod(-2));
    half.add(rod(2));
    half.add(Sphere(Vec3(-2.5, 0, 0), Real(0.2)));
    half.add(Sphere(Vec3(2.5, 0, 0), Real(0.2)));
    const Bsp cut(half, BspBuild::midpoint, 1);
    CHECK(cut.node(cut.root()).axis == 0);
    rods.add(Sphere(Vec3(2.5, 1, 0), Real(0.2)));
    const Bsp skip(rods, BspBuild::midpoint, 1);
    CHECK(skip.node(skip.root()).axis == 1);
    // Three copies of one ball: no plane separates them, so one leaf, not a deep tree of
    // duplicated lists.
    SurfaceList pile;
    for (int k = 0; k < 3; ++k) pile.add(Sphere(Vec3(1, 2, 3), 1));
    const Bsp leaf(pile, BspBuild::midpoint, 1);
    CHECK(leaf.node_count() == 1);
    CHECK(leaf.entries() == 3);
}

TEST_CASE(
    "12.2 every node of a midpoint tree: its plane in the middle of its cell, below on the left, above on the right") {
    // The whole tree over the scene of every kind of primitive, read node by node from the
    // root, the cells worked out from the planes: a tree built with the halves swapped, or
    // with each half's cell swapped, still finds every hit, and only this shows it.
    const SurfaceList list = rt::test::mixed_scene();
    const Bsp bsp(list, BspBuild::midpoint);
    struct Visit {
        BspRef ref;
        Box cell;
        int depth;
    };
    std::vector<Visit> stack{{bsp.root(), bsp.bounding_box(), 0}};
    // The primitives listed anywhere under a node: those the build sorted into it.
    const auto under = [&](BspRef ref) {
        std::vector<std::uint32_t> all;
        std::vector<BspRef> todo{ref};
        while (!todo.empty()) {
            const BspNode& n = bsp.node(todo.back());
            todo.pop_back();
            if (n.leaf()) {
                for (std::uint32_t p : bsp.items(n)) all.push_back(p);
            } else {
                todo.push_back(n.left);
                todo.push_back(n.right);
            }
        }
        return all;
    };
    const Real reach = 2 * bsp.pad();  // BspBuilder::sort's rule
    int inner = 0, failures = 0;
    while (!stack.empty()) {
        const Visit v = stack.back();
        stack.pop_back();
        const BspNode& n = bsp.node(v.ref);
        if (n.leaf()) continue;
        ++inner;
        CAPTURE(v.ref);
        CAPTURE(v.depth);
        CAPTURE(n.axis);
        // The middle to within two units in the last place of the cell's coordinates: (min + max)/2
        // and min + (max - min)/2 can round apart (bsp.hpp).
        const Real low = v.cell.min[n.axis], high = v.cell.max[n.axis];
        RT_CHECK_FIRST(failures,
                       std::abs(n.split - (low + high) / 2) <= 2 * kEps * std::max(std::abs(low), std::abs(high)));
        for (std::uint32_t p : under(n.left))
            RT_CHECK_FIRST(failures, bounding_box(list, bsp.primitive(p)).min[n.axis] <= n.split + reach);
        for (std::uint32_t p : under(n.right))
            RT_CHECK_FIRST(failures, bounding_box(list, bsp.primitive(p)).max[n.axis] >= n.split - reach);
        stack.push_back({n.left, below_plane(v.cell, n.axis, n.split), v.depth + 1});
        stack.push_back({n.right, above_plane(v.cell, n.axis, n.split), v.depth + 1});
    }
    CHECK(inner > 100);
    CHECK(failures == 0);
}

TEST_CASE("12.2 the depth limit: a list that reaches it is a leaf, however long") {
    // Two tiny balls 0.002 apart and a third 10 away. Each cut halves x (the balls lie
    // across the middles of y and z, which the half-copy rule refuses), and the two would
    // need 11 more halvings to part after the first: the limit for 3 primitives,
    // round(8 + 1.3 log2 3) = 10, stops them first, in one leaf at depth 10.
    SurfaceList list;
    for (Real x : {Real(0), Real(0.004), Real(10)}) list.add(Sphere(Vec3(x, 0, 0), Real(0.001)));
    const Bsp bsp(list, BspBuild::midpoint, 1);
    CHECK(bsp.depth() == 10);
    int pairs = 0;
    std::vector<BspRef> todo{bsp.root()};
    while (!todo.empty()) {
        const BspNode& n = bsp.node(todo.back());
        todo.pop_back();
        if (n.leaf())
            pairs += bsp.items(n).size() == 2;
        else
            todo.insert(todo.end(), {n.left, n.right});
    }
    CHECK(pairs == 1);
}

TEST_CASE("12.1 cases 1 and 3: a ray moving away from the plane searches its own side only") {
    const SurfaceList list = two_balls();
    const Bsp bsp(list, BspBuild::midpoint, 1);
    // Case 1: below the plane (x < 0), moving towards -x: the left ball at t = 0.7.
    Search s = search(bsp, list, Ray{Vec3(-1, 0, 0), Vec3(-1, 0, 0)});
    REQUIRE(s.hit);
    CHECK(s.rec.surface == 0);
    CHECK(s.rec.t == doctest::Approx(0.7));
    const std::uint64_t left_side = s.items;
    // Case 3: the mirror image.
    s = search(bsp, list, Ray{Vec3(1, 0, 0), Vec3(1, 0, 0)});
    REQUIRE(s.hit);
    CHECK(s.rec.surface == 1);
    CHECK(s.rec.t == doctest::Approx(0.7));
    // Neither tested the other side's ball: only its own side's two primitives at most.
    CHECK(left_side <= 2);
    CHECK(s.items <= 2);
    // Moving along the plane (d_x = +0 and -0) stays on the side it starts on.
    for (Real zero : {Real(0), -Real(0)}) {
        s = search(bsp, list, Ray{Vec3(-2, 0, 5), Vec3(zero, 0, -1)});
        REQUIRE(s.hit);
        CHECK(s.rec.surface == 0);
        CHECK(s.rec.t == doctest::Approx(4.7));
    }
}

TEST_CASE("12.1 cases 2 and 4: the near side first, the far side only if the near side has no hit") {
    const SurfaceList list = two_balls();
    const Bsp bsp(list, BspBuild::midpoint, 1);
    // Case 2, hit on the near side: the far ball is never tested.
    Search s = search(bsp, list, Ray{Vec3(-5, 0, 0), Vec3(1, 0, 0)});
    REQUIRE(s.hit);
    CHECK(s.rec.surface == 0);
    CHECK(s.rec.t == doctest::Approx(2.7));
    const Search both = search(bsp, list, Ray{Vec3(-5, 0, 0), Vec3(1, 0, 0)}, Interval{3.5, kInfinity});
    CHECK(s.items < both.items);  // past the left ball (t >= 3.5): the far side is searched too
    REQUIRE(both.hit);
    CHECK(both.rec.surface == 1);
    CHECK(both.rec.t == doctest::Approx(6.7));
    // Case 2, nothing ahead on the near side (the left ball is behind the origin).
    s = search(bsp, list, Ray{Vec3(-1, 0, 0), Vec3(1, 0, 0)});
    REQUIRE(s.hit);
    CHECK(s.rec.surface == 1);
    CHECK(s.rec.t == doctest::Approx(2.7));
    // Case 4, the mirror image, with an unnormalised direction.
    s = search(bsp, list, Ray{Vec3(1, 0, 0), Vec3(-2, 0, 0)});
    REQUIRE(s.hit);
    CHECK(s.rec.surface == 0);
    CHECK(s.rec.t == doctest::Approx(1.35));
    // The part ends before the plane: the far side is not visited, and there is no hit.
    s = search(bsp, list, Ray{Vec3(-5, 0.5, -0.5), Vec3(1, 0, 0)}, Interval{0, 4});
    CHECK_FALSE(s.hit);
    const Search whole = search(bsp, list, Ray{Vec3(-5, 0.5, -0.5), Vec3(1, 0, 0)});
    CHECK(s.nodes < whole.nodes);
}

TEST_CASE("12.1 erratum: the course's pseudo-code, given d_x = -0, searches the far side from t = -infinity") {
    // Below the plane, moving along it with a -0 x component: "x_b < 0" is false, so the
    // course computes t = (D - x_a) / -0 = -infinity and searches the right side over
    // [-infinity, t1]: the triangle behind the ray (t = -1) comes back as a hit.
    const SurfaceList list = two_balls();
    const Bsp bsp(list, BspBuild::midpoint, 1);
    const Ray ray{Vec3(-Real(0.25), 0, 0), Vec3(-Real(0), 0, 1)};
    HitRecord course = no_hit_before(kInfinity);
    REQUIRE(course_hit_node(bsp, list, bsp.root(), ray, 0, kInfinity, course));
    CHECK(course.t == doctest::Approx(-1));
    CHECK(course.surface == 2);
    // The four cases written as in exercise 12.1 find nothing, as brute force does.
    HitRecord rec, want;
    CHECK_FALSE(bsp.hit(list, ray, Interval{}, rec));
    CHECK_FALSE(Accel(list, AccelKind::none).hit(list, ray, Interval{}, want));
}

TEST_CASE("12.1 a ray along a cutting plane (d = -0 or +0) searches its own side only, as one moving away does") {
    // Written with the slack and the clamps, "moving away" tested as d < 0 below the plane
    // gets -0 wrong without a wrong hit: t = -infinity and s = infinity make t + s NaN and
    // t - s -infinity, which std::min and std::max turn into the whole part, and the far
    // side is searched over it for nothing. Only the count shows it: a ray along the plane
    // must visit what a ray that moves away from it by a hair visits. The rays pass above
    // the triangle and hit nothing.
    const SurfaceList list = two_balls();
    for (BspBuild how : {BspBuild::midpoint, BspBuild::sah}) {
        const Bsp bsp(list, how, 1);
        for (Real x : {Real(-0.25), Real(0.25)})
            for (Real zero : {-Real(0), Real(0)}) {
                const Search along = search(bsp, list, Ray{Vec3(x, 0, 0), Vec3(zero, zero, 1)});
                const Real away = x < 0 ? -Real(1e-20) : Real(1e-20);
                const Search moving = search(bsp, list, Ray{Vec3(x, 0, 0), Vec3(away, zero, 1)});
                CAPTURE(how == BspBuild::sah);
                CAPTURE(x);
                CAPTURE(std::signbit(zero));
                CHECK_FALSE(along.hit);
                CHECK(along.nodes == moving.nodes);
                CHECK(along.items == moving.items);
            }
    }
}

TEST_CASE("12.1 the far side is searched from the plane on: a cell the ray left before the plane is not visited") {
    // The four balls' tree: x = 0 at the root, y = 0 in each half. From (-5, -3) along
    // (1, 1) the ray crosses y = 0 at t = 3 and x = 0 at t = 5, and hits nothing: it passes
    // through the cells below-left, above-left and above-right, never below-right. Searched
    // from its own start instead of from the plane, the right half would start below y = 0
    // and open that cell too.
    SurfaceList list;
    for (const Vec3& c : {Vec3(-2, -2, 0), Vec3(2, -2, 0), Vec3(-2, 2, 0), Vec3(2, 2, 0)})
        list.add(Sphere(c, Real(0.5)));
    const Bsp bsp(list, BspBuild::midpoint, 1);
    const Ray ray{Vec3(-5, -3, 0), Vec3(1, 1, 0)};
    const Search s = search(bsp, list, ray);
    CHECK_FALSE(s.hit);
    CHECK(s.nodes == 6);  // the root, the two y nodes, and three of the four leaves
    CHECK(s.items == 3);
    CHECK(s.nodes == expected(bsp, list, ray).nodes);
}

TEST_CASE("12.1 a triangle lying in a cutting plane is found from both sides") {
    // Two balls and a square in the plane x = 0, where the midpoint build cuts: it is listed
    // on both sides, and rays crossing it there, or skimming the plane, agree with brute force.
    SurfaceList list;
    list.add(Sphere(Vec3(-2, 0, 0), Real(0.3)));
    list.add(Sphere(Vec3(2, 0, 0), Real(0.3)));
    list.add(Polygon({Vec3(0, -1, -1), Vec3(0, 1, -1), Vec3(0, 1, 1), Vec3(0, -1, 1)}));
    const Bsp bsp(list, BspBuild::midpoint, 1);
    REQUIRE(bsp.node(bsp.root()).split == 0);
    rt::test::Rng rng;
    rt::test::RaySet set;
    for (int k = 0; k < 2000; ++k) {
        const Vec3 on(0, rng(-1, 1), rng(-1, 1));
        const Vec3 o = on + rng.vec(-4, 4);
        set.add(Ray{o, on - o});
    }
    CHECK(rt::test::disagreements(list, set.rays, set.intervals, kBsps) == 0);
}

TEST_CASE("§12.5 the surface-area heuristic cuts off empty space") {
    // Two clusters of balls far apart (x in [-10, -8] and [4, 6]): any plane between them
    // costs the same, and less than any other, so the root's plane falls in the gap.
    SurfaceList list;
    rt::test::Rng rng;
    Real left_end = -kInfinity, right_start = kInfinity;  // the gap between the clusters
    for (int k = 0; k < 40; ++k) {
        list.add(Sphere(Vec3(rng(-9.8, -8.2), rng(-1, 1), rng(-1, 1)), Real(0.2)));
        left_end = std::max(left_end, list.bounding_box().max.x);
    }
    for (int k = 0; k < 40; ++k) {
        const Real x = rng(4.2, 5.8);
        list.add(Sphere(Vec3(x, rng(-1, 1), rng(-1, 1)), Real(0.2)));
        right_start = std::min(right_start, x - Real(0.2));
    }
    const Bsp sah(list, BspBuild::sah);
    const BspNode& root = sah.node(sah.root());
    REQUIRE_FALSE(root.leaf());
    CHECK(root.axis == 0);
    CHECK(root.split > left_end);
    CHECK(root.split < right_start);
    // And per ray it tests fewer primitives than the midpoint tree on the chapter's city.
    Scene city = load_scene_file(kScenes + "city.json");
    RenderOptions o;
    o.width = 48;
    o.height = 36;
    double items[2];
    for (int k = 0; k < 2; ++k) {
        city.build_accel(kBsps[k]);
        items[k] = double(render(city, o).counters.primitives_tested);
    }
    CHECK(items[1] < items[0]);
}

TEST_CASE(
    "12.1 on the library's SAH tree, so with no other exercise: the nodes the four cases visit, and brute force's "
    "hit") {
    // Only exercise 12.1 runs here: the tree comes from the library's build. Each ray must
    // get brute force's hit and visit exactly the nodes and primitives that the four cases
    // of §12.2 visit: a search that finds the right hit with more work (the far side searched
    // after a hit on the near side, or from the part's start instead of the plane, or with
    // no check that the part ends first) is not the exercise. Random rays through the scene
    // of every kind of primitive, and rays at walls in the faces of the tree's box.
    const auto check = [](const SurfaceList& list, const rt::test::RaySet& set) {
        const Bsp bsp(list, BspBuild::sah);
        const Accel brute(list, AccelKind::none);
        int failures = 0;
        for (std::size_t k = 0; k < set.rays.size(); ++k) {
            const Ray& ray = set.rays[k];
            HitRecord want_rec;
            const bool want_hit = brute.hit(list, ray, set.intervals[k], want_rec);
            const Search want = expected(bsp, list, ray, set.intervals[k]);
            const Search got = search(bsp, list, ray, set.intervals[k]);
            CAPTURE(k);
            CAPTURE(ray.origin);
            CAPTURE(ray.direction);
            RT_CHECK_FIRST(failures, got.hit == want_hit);
            if (got.hit && want_hit) {
                RT_CHECK_FIRST(failures, got.rec.t == want_rec.t);
                RT_CHECK_FIRST(failures, got.rec.surface == want_rec.surface);
                RT_CHECK_FIRST(failures, got.rec.primitive == want_rec.primitive);
            }
            RT_CHECK_FIRST(failures, got.nodes == want.nodes);
            RT_CHECK_FIRST(failures, got.items == want.items);
        }
        return failures;
    };
    CHECK(check(rt::test::mixed_scene(), rt::test::random_rays(rt::test::kRandomRays / 5)) == 0);
    const rt::test::Walls walls;
    for (bool outside : {false, true}) {
        CAPTURE(outside);
        CHECK(check(walls.list, walls.rays(outside)) == 0);
    }
}

TEST_CASE("12.1 both builds return brute force's hit on random rays (t, surface and triangle)") {
    const SurfaceList list = rt::test::mixed_scene();
    const rt::test::RaySet set = rt::test::random_rays(rt::test::kRandomRays);
    CHECK(rt::test::disagreements(list, set.rays, set.intervals, kBsps) == 0);
}

TEST_CASE("12.1 rays aimed at a closed mesh's shared edges and vertices, near and far from the origin") {
    // Far from the origin the coordinates' rounding grows: the pad grows with them.
    for (const Vec3& centre : {Vec3(0.3, -0.2, 0.1), Vec3(1000, -2000, 1500)}) {
        CAPTURE(centre.x);
        SurfaceList list;
        const MeshData data = icosphere(centre, 2, 3);
        list.add(Mesh(data));
        list.add(Sphere(centre + Vec3(5, 5, 5), 1));
        rt::test::RaySet all, crossing;
        rt::test::edge_rays(data, centre, all, crossing);
        CHECK(rt::test::disagreements(list, all.rays, all.intervals, kBsps) == 0);
        for (AccelKind kind : kBsps) {
            const Accel bsp(list, kind);
            int lost = 0;
            for (const Ray& r : crossing.rays) {
                HitRecord rec;
                lost += !bsp.hit(list, r, Interval{}, rec);
            }
            CAPTURE(kAccelNames[kind]);
            CHECK(lost == 0);
        }
    }
}

TEST_CASE("12.1 the chapter's scenes render the same image with each BSP as with brute force") {
    for (const char* name : {"city", "sticks", "stadium"}) {
        Scene scene = load_scene_file(kScenes + name + ".json");
        if (std::string(name) == "stadium")
            scene.integrator = make_integrator(Shading::normal);  // cost differs by design
        CAPTURE(name);
        CHECK(rt::test::image_differences(scene, kBsps) == 0);
    }
}

TEST_CASE("12.2 an empty scene, and a scene of one primitive") {
    const SurfaceList empty;
    const Bsp none(empty, BspBuild::midpoint);
    HitRecord rec;
    CHECK_FALSE(none.hit(empty, Ray{Vec3(0), Vec3(0, 0, -1)}, Interval{}, rec));
    CHECK_FALSE(none.occluded(empty, Ray{Vec3(0), Vec3(0, 0, -1)}, Interval{}));
    SurfaceList one;
    one.add(Sphere(Vec3(0, 0, -3), 1));
    for (BspBuild how : {BspBuild::midpoint, BspBuild::sah}) {
        const Bsp bsp(one, how);
        CHECK(bsp.node_count() == 1);
        REQUIRE(bsp.hit(one, Ray{Vec3(0), Vec3(0, 0, -1)}, Interval{}, rec));
        CHECK(rec.t == doctest::Approx(2));
        CHECK(bsp.occluded(one, Ray{Vec3(0), Vec3(0, 0, -1)}, Interval{0, 2.5}));
        CHECK_FALSE(bsp.occluded(one, Ray{Vec3(0), Vec3(0, 0, -1)}, Interval{0, 1.5}));
    }
}
}
