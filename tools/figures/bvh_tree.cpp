// Book §10.2-10.3: a small BVH, built by the library's own build (exercise 10.2's sorted
// halves or 10.3's midpoint, through the same BvhBuilder the Bvh uses) over circles in the
// plane z = 0. Left, every node's box around what it holds, grown a little per level so that
// a parent's outline stays outside its children's; right, the same tree as a tree. Nodes are
// lettered in the order the search of exercise 10.4 reaches them, primitives numbered.
#include "accel/course_bvh.hpp"
#include "geometry/sphere.hpp"
#include "kinds.hpp"

#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

namespace figures {

namespace {

enum class Build { sorted, midpoint };
constexpr auto kBuildNames = rt::names_of<Build>({"sorted", "midpoint"});

}  // namespace

Canvas bvh_tree(const rt::Fields& in) {
    const Build how = in.choice("build", kBuildNames, "build");
    const std::vector<rt::Sphere> spheres = spheres_of(in);
    std::vector<rt::Box> boxes;
    for (const rt::Sphere& s : spheres) boxes.push_back(rt::bounding_box(s));
    if (spheres.size() < 2 || spheres.size() > 26) in.fail("spheres", "needs 2 to 26 circles");

    rt::BvhBuilder builder(boxes);
    std::vector<std::uint32_t> order(spheres.size());
    std::iota(order.begin(), order.end(), 0u);
    const rt::BvhRef root =
        how == Build::sorted ? rt::build_sorted(builder, order, 0) : rt::build_midpoint(builder, order, 0);
    std::vector<rt::CourseBvhNode> nodes = builder.take_nodes();

    std::vector<int> height(nodes.size(), 0);
    auto measure = [&](auto&& self, rt::BvhRef ref) -> int {
        if (rt::is_primitive(ref)) return -1;
        const int h = 1 + std::max(self(self, nodes[ref].left), self(self, nodes[ref].right));
        height[ref] = h;
        return h;
    };
    measure(measure, root);

    Canvas c;
    rt::Box all;
    for (const rt::Box& b : boxes) all.expand(b);
    const double size = double(std::max(all.max.x - all.min.x, all.max.y - all.min.y));
    const double grow = 0.018 * size;  // per level, so nested outlines stay apart

    // The primitives, numbered from 1.
    for (std::size_t p = 0; p < spheres.size(); ++p) {
        c.circle(flat(spheres[p].center), double(spheres[p].radius), Ink::surface);
        c.label(flat(spheres[p].center), std::to_string(p + 1), Ink::axis, 0, -6, Anchor::middle, true);
    }

    // The tree to the right: leaves evenly spaced in search order, each node above the middle
    // of its children.
    const double tree_left = double(all.max.x) + 0.25 * size, leaf_gap = 0.9 * size / double(spheres.size());
    const double level_gap = 0.6 * size / std::max(1, height[root] + 1), tree_top = double(all.max.y);
    int letter = 0, leaf = 0;
    auto draw = [&](auto&& self, rt::BvhRef ref, int depth) -> P2 {
        const double y = tree_top - level_gap * depth;
        if (rt::is_primitive(ref)) {
            const P2 at{tree_left + leaf_gap * leaf++, y};
            c.circle(at, 0.3 * leaf_gap, Ink::surface);
            c.label(at, std::to_string((ref & ~rt::kPrimitiveBit) + 1), Ink::axis, 0, -6, Anchor::middle, true);
            return at;
        }
        const std::string name(1, char('A' + letter++));
        const rt::CourseBvhNode& node = nodes[ref];
        const double g = grow * (height[ref] + 1);
        const P2 lo{double(node.box.min.x) - g, double(node.box.min.y) - g};
        const P2 hi{double(node.box.max.x) + g, double(node.box.max.y) + g};
        c.box(lo, hi, Ink::axis, false);
        c.label(P2{lo.x, hi.y}, name, Ink::axis, 3, -17, Anchor::start, true);
        const P2 l = self(self, node.left, depth + 1), r = self(self, node.right, depth + 1);
        const P2 at{(l.x + r.x) / 2, y};
        const double half = 0.3 * leaf_gap;
        c.line(at, l, Ink::guide);
        c.line(at, r, Ink::guide);
        c.box(at - P2{half, half}, at + P2{half, half}, Ink::axis);
        c.label(at, name, Ink::axis, 0, -6, Anchor::middle, true);
        return at;
    };
    draw(draw, root, 0);
    return c;
}

}  // namespace figures
