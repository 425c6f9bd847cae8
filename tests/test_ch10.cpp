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

// What a build made below `root`: how often each primitive is a leaf (every one must be,
// once), the deepest leaf's depth, and whether every node's box holds its children's.
struct TreeShape {
    std::vector<int> leaf_count;
    int depth = 0;
    bool boxes_hold_children = true;
};
TreeShape shape_of(const std::vector<CourseBvhNode>& nodes, BvhRef root, std::size_t primitives,
                   const std::vector<Box>& boxes) {
    TreeShape shape;
    shape.leaf_count.assign(primitives, 0);
    const auto box_of = [&](BvhRef ref) { return is_primitive(ref) ? boxes[ref & ~kPrimitiveBit] : nodes[ref].box; };
    const auto holds = [](const Box& outer, const Box& inner) {
        return glm::all(glm::lessThanEqual(outer.min, inner.min)) && glm::all(glm::lessThanEqual(inner.max, outer.max));
    };
    std::vector<std::pair<BvhRef, int>> stack{{root, 0}};
    while (!stack.empty()) {
        const auto [ref, d] = stack.back();
        stack.pop_back();
        shape.depth = std::max(shape.depth, d);
        if (is_primitive(ref)) {
            const std::uint32_t p = ref & ~kPrimitiveBit;
            if (p < primitives) ++shape.leaf_count[p];
            continue;
        }
        if (ref >= nodes.size() || d > int(primitives)) {  // a reference past the nodes, or a cycle
            shape.boxes_hold_children = false;
            break;
        }
        const CourseBvhNode& n = nodes[ref];
        shape.boxes_hold_children &= holds(n.box, box_of(n.left)) && holds(n.box, box_of(n.right));
        stack.push_back({n.left, d + 1});
        stack.push_back({n.right, d + 1});
    }
    return shape;
}

bool each_once(const TreeShape& shape) {
    return std::all_of(shape.leaf_count.begin(), shape.leaf_count.end(), [](int c) { return c == 1; });
}

// A tree built by `build` over every box, with what any valid tree has: n - 1 nodes, every
// primitive in one leaf, boxes that hold their children.
template <class Build>
TreeShape checked_tree(const std::vector<Box>& boxes, Build build) {
    BvhBuilder b(boxes);
    std::vector<std::uint32_t> order(boxes.size());
    std::iota(order.begin(), order.end(), 0u);
    const BvhRef root = build(b, std::span<std::uint32_t>(order), 0);
    const auto nodes = b.take_nodes();
    CHECK(nodes.size() == boxes.size() - 1);
    const TreeShape shape = shape_of(nodes, root, boxes.size(), boxes);
    CHECK(each_once(shape));
    CHECK(shape.boxes_hold_children);
    return shape;
}

constexpr AccelKind kStructures[] = {AccelKind::bvh_sort, AccelKind::bvh_midpoint, AccelKind::bvh_sah, AccelKind::fast};

}  // namespace

TEST_SUITE("ch10") {
TEST_CASE("10.1 hit_box: axis-parallel rays with +0 and -0 components") {
    const Real zero = 0, minus_zero = -zero;
    for (const Real x : {zero, minus_zero})
        for (const Real y : {zero, minus_zero}) {
            CAPTURE(x);  // -0 prints as -0
            CAPTURE(y);
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

TEST_CASE("10.1 hit_box: rays lying in a face's plane, along every axis, with +0 and -0 components") {
    // The ray runs in the plane of a face (or along an edge: in two planes), so the slab test
    // computes 0 * inf = NaN there, on whichever axis comes last too. The box is closed: the
    // ray touches it and must hit. Moved off the plane, or pointing away, it misses.
    const Box box{Vec3(-1, 2, 0.5), Vec3(3, 4, 1.5)};
    const Real zero = 0, minus_zero = -zero;
    int failures = 0, cases = 0;
    for (int a = 0; a < 3; ++a)                   // the face's axis
        for (int face = 0; face < 2; ++face)      // its min or max face
            for (int turn = 1; turn < 3; ++turn)  // the axis the ray runs along
                for (const Real sign : {Real(1), Real(-1)})
                    for (int place = 0; place < 3; ++place)  // the third coordinate: a face, the middle, the other face
                        for (int zeros = 0; zeros < 4; ++zeros) {
                            const int b = (a + turn) % 3, c = 3 - a - b;
                            Vec3 o, d;
                            o[a] = face ? box.max[a] : box.min[a];
                            o[c] = place == 0 ? box.min[c] : place == 1 ? (box.min[c] + box.max[c]) / 2 : box.max[c];
                            d[a] = zeros & 1 ? minus_zero : zero;
                            d[c] = zeros & 2 ? minus_zero : zero;
                            d[b] = sign;
                            const Real before = sign > 0 ? box.min[b] - 1 : box.max[b] + 1;  // 1 before the box
                            const Real after = sign > 0 ? box.max[b] + 1 : box.min[b] - 1;   // 1 past it
                            const Real inside = (box.min[b] + box.max[b]) / 2;
                            const Real off = face ? Real(0.25) : Real(-0.25);  // out of the box, off the face
                            struct Case {
                                Vec3 origin;
                                Interval interval;
                                bool hit;
                            };
                            Vec3 o_before = o, o_after = o, o_inside = o, o_off = o;
                            o_before[b] = before;
                            o_after[b] = after;
                            o_inside[b] = inside;
                            o_off[b] = before;
                            o_off[a] += off;
                            for (const Case& k : {Case{o_before, Interval{}, true}, Case{o_inside, Interval{}, true},
                                                  Case{o_before, Interval{0.5, 1}, true},  // ends where it enters
                                                  Case{o_before, Interval{0, 0.5}, false},
                                                  Case{o_after, Interval{}, false}, Case{o_off, Interval{}, false}}) {
                                const Ray ray{k.origin, d};
                                const Interval interval = k.interval;
                                CAPTURE(box);
                                CAPTURE(ray);
                                CAPTURE(interval);
                                RT_CHECK_FIRST(failures, hit_box(box, ray, interval) == k.hit);
                                ++cases;
                            }
                        }
    CHECK(failures == 0);
    CHECK(cases == 3 * 2 * 2 * 2 * 3 * 4 * 6);
}

TEST_CASE("10.1 hit_box: rays through a box's edges and corners are never lost to rounding") {
    // A ray from o through a point p on an edge or a corner of the box, all of them small
    // multiples of 1/8, so that d = p - o is exact and the ray touches the box exactly at
    // t = 1: many only there (they graze it). Each slab's distance (p - o) * (1 / d) rounds
    // to 1 give or take an ulp, so the entry can come out an ulp after the exit: without the
    // padding of the far end, about one grazing ray in twenty loses the box.
    pcg32 gen(17);
    const auto eighths = [&](int lo, int hi) { return Real(lo * 8 + int(gen(std::uint32_t((hi - lo) * 8 + 1)))) / 8; };
    const auto point = [&](int lo, int hi) {  // x, y, z drawn in that order
        Vec3 p;
        for (int a = 0; a < 3; ++a) p[a] = eighths(lo, hi);
        return p;
    };
    int failures = 0, grazing = 0;
    for (int k = 0; k < 20000; ++k) {
        Box box;
        box.expand(point(-8, 8));
        box.expand(point(-8, 8));
        // p: each coordinate on the box's min or max, but one (an edge) or none (a corner)
        // anywhere between.
        const int free_axis = k % 4;  // 3: a corner
        Vec3 p;
        for (int a = 0; a < 3; ++a)
            p[a] = a == free_axis ? box.min[a] + (box.max[a] - box.min[a]) * Real(gen(9)) / 8
                                  : (gen(2) ? box.max[a] : box.min[a]);
        const Vec3 o = point(-24, 24);
        if (o == p) continue;
        const Ray ray{o, p - o};
        // Grazing: the ray is outside the box just before and just after p.
        const auto inside = [&](const Vec3& q) {
            return q.x > box.min.x && q.x < box.max.x && q.y > box.min.y && q.y < box.max.y && q.z > box.min.z &&
                   q.z < box.max.z;
        };
        grazing += !inside(ray.at(Real(0.999))) && !inside(ray.at(Real(1.001)));
        for (const Interval interval : {Interval{}, Interval{0, 1}, Interval{1, 2}}) {
            CAPTURE(k);
            CAPTURE(box);
            CAPTURE(ray);
            CAPTURE(interval);
            RT_CHECK_FIRST(failures, hit_box(box, ray, interval));
        }
    }
    CHECK(failures == 0);
    CHECK(grazing > 5000);
}

TEST_CASE("10.1 hit_box agrees with the library's cull (might_hit) on 10^5 random rays and boxes") {
    Rng rng;
    int failures = 0, hits = 0;
    for (int k = 0; k < 100000; ++k) {
        Box box;
        box.expand(rng.vec(-2, 2));
        box.expand(rng.vec(-2, 2));
        Vec3 d = rng.vec(-1, 1);
        if (k % 4 == 0) d[k / 4 % 3] = (k & 8) ? Real(0) : -Real(0);  // axis-parallel a quarter of the time
        const Ray ray{rng.vec(-3, 3), d};
        const Interval interval{k % 3 == 0 ? rng(0, 2) : Real(0), k % 5 == 0 ? rng(0, 4) : kInfinity};
        const bool want = might_hit(box, ray, interval);
        hits += want;
        CAPTURE(k);
        CAPTURE(box);
        CAPTURE(ray);
        CAPTURE(interval);
        RT_CHECK_FIRST(failures, hit_box(box, ray, interval) == want);
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
        CAPTURE(n);
        const TreeShape shape = checked_tree(boxes, build_sorted);
        // Either half may take the odd one out: the depth is the same.
        CHECK(shape.depth == int(std::ceil(std::log2(double(n)))));
    }
}

TEST_CASE("10.3 build_midpoint: split at the middle of the box, halve when all centres fall on one side") {
    // Centres at x = 0, 0.1, 0.2 and 10: the middle of the box [-0.1, 10.1] is 5, so the
    // three close ones go to one side and the far one to the other, a split by count would
    // not do that. (Which side is which, the contract leaves open.)
    std::vector<Box> boxes;
    for (const Real x : {10.0, 0.0, 0.2, 0.1}) boxes.push_back(Box{Vec3(x - 0.1, 0, 0), Vec3(x + 0.1, 1, 1)});
    BvhBuilder b(boxes);
    std::vector<std::uint32_t> order{0, 1, 2, 3};
    const BvhRef root = build_midpoint(b, order, 0);
    auto nodes = b.take_nodes();
    REQUIRE(nodes.size() == 3);
    const CourseBvhNode& top = nodes[root];
    const bool far_right = top.right == b.primitive(0), far_left = top.left == b.primitive(0);
    CHECK((far_left || far_right));
    const BvhRef near = far_left ? top.right : top.left;
    REQUIRE_FALSE(is_primitive(near));
    CHECK(nodes[near].box.max.x == doctest::Approx(0.3));
    CHECK(each_once(shape_of(nodes, root, boxes.size(), boxes)));

    // Identical boxes: no plane separates their centres, so the list is halved (the course's
    // pseudo-code recurses here forever, and the test program crashes).
    std::vector<Box> same(5, Box{Vec3(0), Vec3(1)});
    BvhBuilder b2(same);
    std::vector<std::uint32_t> order2{0, 1, 2, 3, 4};
    const BvhRef root2 = build_midpoint(b2, order2, 1);
    nodes = b2.take_nodes();
    CHECK(nodes.size() == 4);
    REQUIRE_FALSE(is_primitive(root2));
    CHECK(each_once(shape_of(nodes, root2, same.size(), same)));
}

TEST_CASE("10.3 build_midpoint: every primitive once, in clusters of equal centres and among large boxes") {
    // Random boxes, some stacked on the same centre (the halving at depth), some long enough
    // to stretch the box past the others' centres (every centre on one side of the middle).
    for (const int n : {2, 3, 7, 64, 500}) {
        Rng rng;
        std::vector<Box> boxes;
        for (int k = 0; k < n; ++k) {
            const Vec3 c = k % 3 == 0 && k > 0
                               ? (boxes[std::size_t(k - 1)].min + boxes[std::size_t(k - 1)].max) / Real(2)
                               : rng.vec(-10, 10);
            const Vec3 half = k % 5 == 4 ? Vec3(30, 0.1, 0.1) : Vec3(rng(0.05, 0.5));
            boxes.push_back(Box{c - half, c + half});
        }
        CAPTURE(n);
        checked_tree(boxes,
                     [](BvhBuilder& b, std::span<std::uint32_t> p, int axis) { return build_midpoint(b, p, axis); });
    }
}

TEST_CASE("10.4 every structure returns brute force's hit on random rays (t, surface and triangle)") {
    const SurfaceList list = mixed_scene();
    const rt::test::RaySet set = rt::test::random_rays(rt::test::kRandomRays);
    CHECK(disagreements(list, set.rays, set.intervals, kStructures) == 0);
}

TEST_CASE("10.4 rays from one point searched as a packet get brute force's hits, ray by ray") {
    // A pinhole camera's rays are searched eight at a time (book §10.5): every ray must get
    // exactly its own hit, on every kind of primitive (the upper level's spheres, meshes and
    // instances) and for a mesh alone (the packet walks the mesh's own tree).
    const SurfaceList list = mixed_scene();
    int searched = 0;
    const std::vector<rt::test::Packet> packets = rt::test::camera_packets(rt::test::kRandomRays / 8, 6);
    CHECK(rt::test::packet_disagreements(list, packets, kStructures, &searched) == 0);
    CHECK(searched > int(packets.size()) * 3 / 4);  // most went as packets: the packet search was tested
    SurfaceList mesh;
    mesh.add(Mesh(icosphere(Vec3(0.3, -0.2, 0.1), 2, 3)));
    CHECK(rt::test::packet_disagreements(mesh, rt::test::camera_packets(4000, 2), kStructures, &searched) == 0);
    CHECK(searched > 3000);
}

TEST_CASE(
    "10.4 packets of rays at a closed mesh's shared edges and vertices, and packets that cannot be, lose nothing") {
    // Eight rays from one point through vertices and edge midpoints of an icosphere (ties
    // between triangles: each ray must get brute force's triangle); packets whose rays leave
    // different points, point into different octants, have a zero or subnormal direction
    // component, or start behind the origin are searched ray by ray, with the same answers.
    SurfaceList list;
    const MeshData data = icosphere(Vec3(0.3, -0.2, 0.1), 2, 3);
    list.add(Mesh(data));
    rt::test::Rng rng;
    std::vector<rt::test::Packet> packets;
    for (std::size_t t = 0; t + 8 <= data.triangles.size(); t += 8) {
        rt::test::Packet p;
        const Vec3 eye = rng.vec(-9, 9) * Real(1.5);
        for (std::size_t k = t; k < t + 8; ++k) {
            const auto& tri = data.triangles[k];
            const Vec3 a = data.positions[tri[0]], b = data.positions[tri[1]];
            p.rays.push_back(Ray{eye, (k % 2 ? a : (a + b) * Real(0.5)) - eye});
        }
        packets.push_back(p);
    }
    int searched = 0;
    CHECK(rt::test::packet_disagreements(list, packets, kStructures, &searched) == 0);
    CHECK(searched > 0);  // those in one octant went together
    std::vector<rt::test::Packet> refused;
    const Vec3 eye(0.2, 4, 3);
    const auto aimed = [&](Vec3 d) {
        rt::test::Packet p;
        for (int k = 0; k < 8; ++k) p.rays.push_back(Ray{eye, Vec3(0.3, -0.2, 0.1) - eye + Real(0.1) * Real(k) * d});
        return p;
    };
    refused.push_back(aimed(Vec3(1, 0, 0)));
    refused.back().rays[3].origin.x += Real(1e-3);  // another origin
    refused.push_back(aimed(Vec3(0, 0, 40)));       // the last rays turn to +z: another octant
    refused.push_back(aimed(Vec3(0, 0, 0)));
    refused.back().rays[5].direction.x = 0;  // a zero component
    refused.push_back(aimed(Vec3(0, 0, 0)));
    refused.back().rays[2].direction.x = Real(-0.0);
    refused.push_back(aimed(Vec3(0, 0, 0)));
    refused.back().rays[6].direction.x = Real(1e-40);  // a float subnormal
    refused.push_back(aimed(Vec3(0, 0, 0)));
    refused.back().interval = Interval{-1, kInfinity};  // starts behind the eye
    for (const rt::test::Packet& p : refused) {
        WidePacket wide;
        CHECK_FALSE(make_packet(p.rays, p.interval, wide));
    }
    CHECK(rt::test::packet_disagreements(list, refused, kStructures) == 0);
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
        rt::test::RaySet set = rt::test::random_rays(rt::test::kRandomRays / 2), crossing;
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
    CAPTURE(work[AccelKind::bvh_midpoint]);
    CHECK(work[AccelKind::none] > 500);  // 578 primitives, and any-hit rays stop early
    CHECK(work[AccelKind::bvh_sort] < work[AccelKind::none] / 5);
    CHECK(work[AccelKind::bvh_midpoint] < work[AccelKind::none] / 5);
    CHECK(work[AccelKind::bvh_sah] <= work[AccelKind::bvh_sort]);
}
}
