// Chapter 10: bounding boxes and the BVH (course §9.9.1-9.9.2). The slab test on the rays
// that break naive versions (+0 and -0 directions, origins on faces and edges, flat boxes),
// the course's two builds on worked examples, and every structure against brute force:
// the same closest hit (t, surface and triangle) and the same any-hit answer, on random rays
// and on rays aimed exactly at a closed mesh's shared edges and vertices.
#include "accel/accel.hpp"
#include "geometry/procedural.hpp"
#include "io/scene_file.hpp"
#include "render/render.hpp"
#include "support.hpp"
#include "support/accel_check.hpp"
#include "support/source_dir.hpp"

#include <pcg_random.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <type_traits>

using namespace rt;
using rt::test::disagreements;
using rt::test::mixed_scene;
using rt::test::Rng;

namespace {

const std::string kScenes = rt::test::source_dir() + "/chapters/ch10_bvh/scenes/";
const Box kUnit{Vec3(0), Vec3(1)};
constexpr AccelKind kStructures[] = {AccelKind::bvh_sort, AccelKind::bvh_midpoint, AccelKind::bvh_sah, AccelKind::fast};

}  // namespace

TEST_SUITE("ch10") {
TEST_CASE("10.1 hit_box: axis-parallel rays with +0 and -0 components") {
    const Real zero = 0, minus_zero = -zero;
    for (const Real x : {zero, minus_zero})
        for (const Real y : {zero, minus_zero}) {
            CAPTURE(std::signbit(x));
            CAPTURE(std::signbit(y));
            // Straight through the box along z, from either side.
            CHECK(hit_box(kUnit, Ray{Vec3(0.5, 0.5, -1), Vec3(x, y, 1)}, Interval{}));
            CHECK(hit_box(kUnit, Ray{Vec3(0.5, 0.5, 2), Vec3(x, y, -1)}, Interval{}));
            // Beside the box: x = 2 lies outside the x slab whatever the sign of the zero.
            CHECK_FALSE(hit_box(kUnit, Ray{Vec3(2, 0.5, -1), Vec3(x, y, 1)}, Interval{}));
            CHECK_FALSE(hit_box(kUnit, Ray{Vec3(0.5, -1, -1), Vec3(x, y, 1)}, Interval{}));
            // Pointing away from the box.
            CHECK_FALSE(hit_box(kUnit, Ray{Vec3(0.5, 0.5, -1), Vec3(x, y, -1)}, Interval{}));
        }
}

TEST_CASE("10.1 hit_box: rays starting on a face or an edge, and rays lying in a face's plane") {
    CHECK(hit_box(kUnit, Ray{Vec3(0, 0.5, 0.5), Vec3(1, 0, 0)}, Interval{}));  // on a face, inwards
    CHECK(hit_box(kUnit, Ray{Vec3(0, 0, 0.5), Vec3(1, 1, 0)}, Interval{}));    // on an edge, inwards
    CHECK(hit_box(kUnit, Ray{Vec3(0, 0.5, -1), Vec3(0, 0, 1)}, Interval{}));   // in the plane x = 0
    CHECK(hit_box(kUnit, Ray{Vec3(0, 0, -1), Vec3(0, 0, 1)}, Interval{}));     // along an edge
    CHECK(hit_box(kUnit, Ray{Vec3(1, 1, 1), Vec3(1, 1, 1)}, Interval{}));      // leaving from a corner: t = 0
    CHECK_FALSE(hit_box(kUnit, Ray{Vec3(1, 1, 1), Vec3(1, 1, 1)}, Interval{1e-3, kInfinity}));
    // The interval counts: the box lies between t = 1 and t = 2 on this ray.
    const Ray r{Vec3(0.5, 0.5, -1), Vec3(0, 0, 1)};
    CHECK(hit_box(kUnit, r, Interval{0, 1}));
    CHECK(hit_box(kUnit, r, Interval{1.5, 1.6}));
    CHECK(hit_box(kUnit, r, Interval{2, 5}));
    CHECK_FALSE(hit_box(kUnit, r, Interval{0, 0.99}));
    CHECK_FALSE(hit_box(kUnit, r, Interval{2.01, 5}));
}

TEST_CASE("10.1 hit_box: a box of zero thickness (a flat quad's) and NaN") {
    const Box flat{Vec3(0, 0, 0), Vec3(1, 0, 1)};
    CHECK(hit_box(flat, Ray{Vec3(0.5, 1, 0.5), Vec3(0, -1, 0)}, Interval{}));
    CHECK(hit_box(flat, Ray{Vec3(0.5, -1, 0.5), Vec3(0.1, 1, -0.2)}, Interval{}));
    CHECK(hit_box(flat, Ray{Vec3(-1, 0, 0.5), Vec3(1, 0, 0)}, Interval{}));  // in its plane
    CHECK_FALSE(hit_box(flat, Ray{Vec3(-1, 0.1, 0.5), Vec3(1, 0, 0)}, Interval{}));
    CHECK_FALSE(hit_box(flat, Ray{Vec3(2, 1, 0.5), Vec3(0, -1, 0)}, Interval{}));
    // A NaN far end is never a hit.
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    CHECK_FALSE(hit_box(kUnit, Ray{Vec3(0.5, 0.5, -1), Vec3(0, 0, 1)}, Interval{0, nan}));
    CHECK_FALSE(hit_box(Box{}, Ray{Vec3(0.5, 0.5, -1), Vec3(0, 0, 1)}, Interval{}));  // the empty box
}

TEST_CASE("10.1 hit_box agrees with the library's cull (might_hit) on 10^5 random rays and boxes") {
    Rng rng;
    int failures = 0, hits = 0;
    for (int k = 0; k < 100000; ++k) {
        Box b;
        b.expand(rng.vec(-2, 2));
        b.expand(rng.vec(-2, 2));
        Vec3 d = rng.vec(-1, 1);
        if (k % 4 == 0) d[k / 4 % 3] = (k & 8) ? Real(0) : -Real(0);  // axis-parallel a quarter of the time
        const Ray ray{rng.vec(-3, 3), d};
        const Interval iv{k % 3 == 0 ? rng(0, 2) : Real(0), k % 5 == 0 ? rng(0, 4) : kInfinity};
        const bool want = might_hit(b, ray, iv);
        hits += want;
        CAPTURE(k);
        RT_CHECK_FIRST(failures, hit_box(b, ray, iv) == want);
    }
    CHECK(failures == 0);
    CHECK(hits > 2000);  // the sample exercises both answers
    CHECK(hits < 90000);
}

TEST_CASE("10.2 build_sorted: the course's halving by sorted centres, cycling the axes") {
    // Four unit boxes with centres at x = 3, 1, 0, 2; y increasing the other way.
    std::vector<Box> boxes;
    for (const Real x : {3, 1, 0, 2}) boxes.push_back(Box{Vec3(x - 0.5, 3 - x, 0), Vec3(x + 0.5, 4 - x, 1)});
    BvhBuilder b(boxes);
    std::vector<std::uint32_t> order{0, 1, 2, 3};
    const BvhRef root = build_sorted(b, order, 0);
    REQUIRE_FALSE(is_primitive(root));
    const auto nodes = b.take_nodes();
    REQUIRE(nodes.size() == 3);  // n - 1 nodes for n primitives, one a leaf
    const CourseBvhNode& top = nodes[root];
    // Sorted by x: 2 (x = 0), 1 (x = 1) | 3 (x = 2), 0 (x = 3); each half then sorted by y.
    const CourseBvhNode& left = nodes[top.left];
    const CourseBvhNode& right = nodes[top.right];
    CHECK(left.box.min.x == Real(-0.5));
    CHECK(left.box.max.x == Real(1.5));
    CHECK(right.box.min.x == Real(1.5));
    CHECK(right.box.max.x == Real(3.5));
    // Within the left half, the lower y (primitive 1, y in [2, 3]) comes first.
    CHECK(left.left == b.primitive(1));
    CHECK(left.right == b.primitive(2));
    CHECK(right.left == b.primitive(0));
    CHECK(right.right == b.primitive(3));
    CHECK(top.box.min == Vec3(-0.5, 0, 0));
    CHECK(top.box.max == Vec3(3.5, 4, 1));
}

TEST_CASE("10.2 build_sorted is balanced: depth ceil(log2 n), as the course's analysis says") {
    for (const int n : {1, 2, 3, 5, 8, 100, 1000, 1025}) {
        std::vector<Box> boxes;
        Rng rng;
        for (int k = 0; k < n; ++k) {
            const Vec3 c = rng.vec(-10, 10);
            boxes.push_back(Box{c - Real(0.1), c + Real(0.1)});
        }
        BvhBuilder b(boxes);
        std::vector<std::uint32_t> order(static_cast<std::size_t>(n));
        std::iota(order.begin(), order.end(), 0u);
        const BvhRef root = build_sorted(b, order, 0);
        const auto nodes = b.take_nodes();
        CAPTURE(n);
        CHECK(nodes.size() == std::size_t(n - 1));
        // Depth of every primitive below the root.
        int deepest = 0;
        std::vector<std::pair<BvhRef, int>> stack{{root, 0}};
        while (!stack.empty()) {
            const auto [ref, d] = stack.back();
            stack.pop_back();
            deepest = std::max(deepest, d);
            if (is_primitive(ref)) continue;
            stack.push_back({nodes[ref].left, d + 1});
            stack.push_back({nodes[ref].right, d + 1});
        }
        CHECK(deepest == int(std::ceil(std::log2(double(n)))));
    }
}

TEST_CASE("10.3 build_midpoint: split at the middle of the box, halve when all centres fall on one side") {
    // Centres at x = 0, 0.1, 0.2 and 10: the middle of the box [-0.1, 10.1] is 5, so the
    // three close ones go left and the far one right, a split by count would not do that.
    std::vector<Box> boxes;
    for (const Real x : {10.0, 0.0, 0.2, 0.1}) boxes.push_back(Box{Vec3(x - 0.1, 0, 0), Vec3(x + 0.1, 1, 1)});
    BvhBuilder b(boxes);
    std::vector<std::uint32_t> order{0, 1, 2, 3};
    const BvhRef root = build_midpoint(b, order, 0);
    auto nodes = b.take_nodes();
    REQUIRE(nodes.size() == 3);
    const CourseBvhNode& top = nodes[root];
    CHECK(top.right == b.primitive(0));
    REQUIRE_FALSE(is_primitive(top.left));
    CHECK(nodes[top.left].box.max.x == doctest::Approx(0.3));

    // Identical boxes: no plane separates their centres, so the list is halved.
    std::vector<Box> same(5, Box{Vec3(0), Vec3(1)});
    BvhBuilder b2(same);
    std::vector<std::uint32_t> order2{0, 1, 2, 3, 4};
    const BvhRef root2 = build_midpoint(b2, order2, 1);
    nodes = b2.take_nodes();
    CHECK(nodes.size() == 4);
    REQUIRE_FALSE(is_primitive(root2));
}

TEST_CASE("10.4 every structure returns brute force's hit on 10^5 random rays (t, surface and triangle)") {
    const SurfaceList list = mixed_scene();
    const rt::test::RaySet set = rt::test::random_rays(rt::test::kRandomRays);
    CHECK(disagreements(list, set.rays, set.intervals, kStructures) == 0);
}

TEST_CASE("10.4 rays aimed exactly at a closed mesh's shared edges and vertices are never lost") {
    // Rays through the vertices and edge midpoints of an icosphere, from outside: each hits
    // (the mesh is closed and the triangle test watertight), and no structure loses one to
    // a box test's rounding or picks another triangle than brute force at a tie.
    SurfaceList list;
    const MeshData data = icosphere(Vec3(0.3, -0.2, 0.1), 2, 3);
    list.add(Mesh(data));
    rt::test::RaySet all, crossing;
    rt::test::edge_rays(data, Vec3(0.3, -0.2, 0.1), all, crossing);
    CHECK(disagreements(list, all.rays, all.intervals, kStructures) == 0);
    const Accel fast(list, AccelKind::fast);
    int lost = 0;
    for (const Ray& r : crossing.rays) {
        HitRecord rec;
        if (!fast.hit(list, r, Interval{}, rec)) ++lost;
    }
    CHECK(lost == 0);
}

TEST_CASE("10.4 axis-parallel rays with +0 and -0 components, in the planes of the tree's boxes, are never lost") {
    // A cube cut into a 4 x 4 grid per face: every vertex coordinate is a multiple of 1/2,
    // so the boxes of the tree lie in those planes. Rays along an axis, their other two
    // components +0 or -0, start in those planes and between them: there the slab test
    // computes 0 * inf, a NaN that must keep the box (a box lost there loses a hit).
    SurfaceList list;
    const MeshData data = subdivided_cube(Vec3(0), 2, 4);
    list.add(Mesh(data));
    rt::test::RaySet set;
    int through_faces = 0;
    for (int axis = 0; axis < 3; ++axis)
        for (Real sign : {Real(1), Real(-1)})
            for (int i = -4; i <= 4; ++i)
                for (int j = -4; j <= 4; ++j)
                    for (int zeros = 0; zeros < 4; ++zeros)
                        for (Real start : {Real(-3), Real(0)}) {
                            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
                            Vec3 o, d;
                            o[axis] = sign * start;
                            o[u] = Real(i) / 4;
                            o[v] = Real(j) / 4;
                            d[axis] = sign;
                            d[u] = zeros & 1 ? Real(-0.0) : Real(0.0);
                            d[v] = zeros & 2 ? Real(-0.0) : Real(0.0);
                            set.add(Ray{o, d});
                            set.add(Ray{o, d}, Interval{0.5, 3.5});
                            through_faces += std::abs(i) < 4 && std::abs(j) < 4;
                        }
    CHECK(disagreements(list, set.rays, set.intervals, kStructures) == 0);
    // And the answer itself: a ray inside the cube's outline meets a face ahead, whether it
    // starts outside (at 3) or at the centre.
    const Accel fast(list, AccelKind::fast);
    int hits = 0;
    for (std::size_t k = 0; k < set.rays.size(); k += 2) {
        const Ray& r = set.rays[k];
        const int axis = r.direction.x != 0 ? 0 : r.direction.y != 0 ? 1 : 2;
        const Vec3 o = r.origin;
        if (std::abs(o[(axis + 1) % 3]) < 1 && std::abs(o[(axis + 2) % 3]) < 1) {
            HitRecord rec;
            hits += fast.hit(list, r, Interval{}, rec) && rec.t == (o[axis] == 0 ? 1 : 2);
        }
    }
    CHECK(hits == through_faces);
}

TEST_CASE("10.4 a mesh's blocks test with their own float corners where float holds them, and agree either way") {
    // The exact test needs the corners in Real. A mesh whose coordinates are floats (any OBJ
    // file) has them in its blocks already; another keeps a second array (MeshAccel::corners).
    // Both must give brute force's hits, bit for bit, on random rays and at shared edges.
    // With Real = float every mesh is of the first kind.
    const Vec3 centre(0.3, -0.2, 0.1);
    MeshData inexact = icosphere(centre, 2, 3), exact = inexact;
    for (Vec3& p : exact.positions) p = Vec3(round_to_float(p.x), round_to_float(p.y), round_to_float(p.z));
    constexpr bool real_is_float = std::is_same_v<Real, float>;
    int float_coordinates = 0;
    for (const Vec3& p : inexact.positions)
        for (int a = 0; a < 3; ++a) float_coordinates += round_to_float(p[a]) == p[a];
    CHECK((float_coordinates == 3 * int(inexact.positions.size())) == real_is_float);
    for (const MeshData* data : {&exact, &inexact}) {
        SurfaceList list;
        list.add(Mesh(*data));
        const MeshAccel& accel = std::get<Mesh>(list[0].shape).accel();
        const bool all_exact = data == &exact || real_is_float;
        CHECK(accel.corners.empty() == all_exact);
        CHECK(std::all_of(accel.blocks.begin(), accel.blocks.end(), [](const TriangleBlock& b) { return b.exact; }) ==
              all_exact);
        rt::test::RaySet set = rt::test::random_rays(20000), crossing;
        rt::test::edge_rays(*data, centre, set, crossing);
        CHECK(disagreements(list, set.rays, set.intervals, kStructures) == 0);
    }
}

TEST_CASE("10.4 the chapter's scenes render the same image with every structure, bit for bit") {
    for (const char* name : {"spheres", "soup"}) {
        CAPTURE(name);
        CHECK(rt::test::image_differences(load_scene_file(kScenes + name + ".json"), kStructures) == 0);
    }
}

TEST_CASE("10.4 a tree tests far fewer primitives per ray than brute force, the SAH tree fewest") {
    // The course's promise, sub-linear search, measured in work rather than time: the same
    // on every machine.
    Scene scene = load_scene_file(kScenes + "spheres.json");
    RenderOptions o;
    o.width = 64;
    o.height = 48;
    std::map<AccelKind, double> work;
    for (AccelKind kind : {AccelKind::none, AccelKind::bvh_sort, AccelKind::bvh_midpoint, AccelKind::bvh_sah}) {
        scene.build_accel(kind);
        const RayCounters c = render(scene, o).counters;
        work[kind] = double(c.nodes_visited + c.primitives_tested) / double(c.total());
    }
    CAPTURE(work[AccelKind::none]);
    CAPTURE(work[AccelKind::bvh_sort]);
    CAPTURE(work[AccelKind::bvh_sah]);
    CHECK(work[AccelKind::none] > 500);  // 578 primitives, and any-hit rays stop early
    CHECK(work[AccelKind::bvh_sort] < work[AccelKind::none] / 5);
    CHECK(work[AccelKind::bvh_midpoint] < work[AccelKind::none] / 5);
    CHECK(work[AccelKind::bvh_sah] <= work[AccelKind::bvh_sort]);
}
}
