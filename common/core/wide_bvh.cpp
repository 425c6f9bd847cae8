#include "core/wide_bvh.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>

namespace rt {

namespace {

float half_area(const BvhNode& n) {
    const float x = n.hi[0] - n.lo[0], y = n.hi[1] - n.lo[1], z = n.hi[2] - n.lo[2];
    return x * y + y * z + z * x;
}

// Which binary nodes become each wide node's children, chosen to make the expected number
// of node visits least (Ylitie, Karras and Laine 2017, without their leaf choice: a
// binary leaf stays a leaf). A ray visits a node with a probability that grows with its
// box's area, so the cost of a tree is the sum of its wide nodes' areas, and for every
// binary node n and k = 1..W the cheapest way to hang n's subtree from at most k slots of
// its parent is found bottom-up:
//   roots(n, 1) = n itself: a wide node (area(n) + split(n, W)), or a leaf;
//   roots(n, k) = the cheaper of n itself and split(n, k), where
//   split(n, k) = min over j of roots(left, j) + roots(right, k - j).
// Opening the largest child first until W, top-down, fills the nodes at the top but leaves
// a crowd of nodes with two or three children above the leaves; this fills both.
template <int W>
struct Gather {
    const FlatBvh& bvh;
    std::vector<std::array<float, W + 1>> cost;      // cost[n][k]: roots(n, k); [0] unused
    std::vector<std::array<std::uint8_t, W + 1>> j;  // split(n, k)'s j, or 0 where n itself is cheaper

    explicit Gather(const FlatBvh& b) : bvh(b), cost(b.nodes.size()), j(b.nodes.size()) {}

    // Bottom-up: children are numbered after their parent (core/flat_bvh.cpp), so a reverse
    // sweep meets them first, with no recursion.
    void run() {
        for (std::size_t n = bvh.nodes.size(); n-- > 0;) {
            const BvhNode& node = bvh.nodes[n];
            auto& c = cost[n];
            if (node.leaf()) {
                c.fill(0);
                j[n].fill(0);
                continue;
            }
            const auto& l = cost[node.first];
            const auto& r = cost[node.first + 1];
            float split[W + 1];
            std::uint8_t at[W + 1] = {};
            for (int k = 2; k <= W; ++k) {
                split[k] = std::numeric_limits<float>::infinity();
                for (int i = 1; i < k; ++i)
                    if (l[i] + r[k - i] < split[k]) {
                        split[k] = l[i] + r[k - i];
                        at[k] = std::uint8_t(i);
                    }
            }
            const float self = half_area(node) + split[W];
            c[1] = self;
            j[n][1] = 0;
            for (int k = 2; k <= W; ++k) {
                c[k] = split[k] < self ? split[k] : self;
                j[n][k] = split[k] < self ? at[k] : 0;
            }
        }
    }

    // The binary nodes that hang subtree n from at most k slots.
    void collect(std::uint32_t n, int k, std::uint32_t* out, int& count) const {
        if (j[n][k] == 0) {
            out[count++] = n;
            return;
        }
        const std::uint32_t left = bvh.nodes[n].first;
        collect(left, j[n][k], out, count);
        collect(left + 1, k - j[n][k], out, count);
    }

    int kids(std::uint32_t n, std::uint32_t (&out)[W]) const {
        int count = 0;
        const std::uint32_t left = bvh.nodes[n].first;
        const int i = j_split(n);
        collect(left, i, out, count);
        collect(left + 1, W - i, out, count);
        return count;
    }

    // The j of split(n, W): where n is a wide node, its W slots shared between its children.
    int j_split(std::uint32_t n) const {
        const auto& l = cost[bvh.nodes[n].first];
        const auto& r = cost[bvh.nodes[n].first + 1];
        int best = 1;
        for (int i = 2; i < W; ++i)
            if (l[i] + r[W - i] < l[best] + r[W - best]) best = i;
        return best;
    }
};

// The slots near to far along each octant's diagonal (WideNode::order): by the box
// centre's distance along it, empty slots last.
template <int W>
void set_order(WideNode<W>& node, int n) {
    for (int octant = 0; octant < 8; ++octant) {
        double key[W];
        int slots[W];
        for (int c = 0; c < W; ++c) {
            slots[c] = c;
            key[c] = 0;
            for (int a = 0; a < 3; ++a) {
                const double centre = double(node.lo[a][c]) + double(node.hi[a][c]);
                key[c] += octant >> a & 1 ? -centre : centre;
            }
        }
        std::stable_sort(slots, slots + n, [&](int x, int y) { return key[x] < key[y]; });
        for (int p = 0; p < W; ++p) node.order[p] |= std::uint32_t(slots[p]) << 3 * octant;
    }
}

// Writes wide node `at` for binary node `b`, its inner children after it, depth first.
template <int W>
void emit(const FlatBvh& bvh, const Gather<W>& g, std::uint32_t b, WideBvh<W>& out, std::uint32_t at) {
    WideNode<W> node{};
    constexpr float inf = std::numeric_limits<float>::infinity();
    std::uint32_t kids[W];
    const int n = g.kids(b, kids);
    for (int c = 0; c < W; ++c)
        for (int a = 0; a < 3; ++a) {
            node.lo[a][c] = c < n ? bvh.nodes[kids[c]].lo[a] : inf;
            node.hi[a][c] = c < n ? bvh.nodes[kids[c]].hi[a] : -inf;
        }
    for (int c = 0; c < n; ++c) {
        const BvhNode& k = bvh.nodes[kids[c]];
        if (k.leaf()) {
            if (k.first > kMaxLeafFirst || k.count > kMaxLeafCount)
                throw std::length_error("wide BVH: a leaf beyond what a child reference holds");
            node.child[c] = leaf_ref(k.first, k.count);
        } else {
            node.child[c] = std::uint32_t(out.nodes.size());
            out.nodes.emplace_back();
            emit(bvh, g, kids[c], out, node.child[c]);
        }
    }
    set_order(node, n);
    out.nodes[at] = node;
}

}  // namespace

template <int W>
WideBvh<W> collapse(const FlatBvh& bvh) {
    WideBvh<W> out;
    if (bvh.nodes.empty()) return out;
    if (bvh.nodes[0].leaf()) {
        out.root_is_leaf = true;
        out.root_count = bvh.nodes[0].count;
        return out;
    }
    Gather<W> g(bvh);
    g.run();
    out.nodes.reserve(bvh.nodes.size() / (W - 1) + 1);
    out.nodes.emplace_back();
    emit(bvh, g, 0, out, 0);
    return out;
}

template WideBvh<4> collapse<4>(const FlatBvh&);
template WideBvh<8> collapse<8>(const FlatBvh&);

}  // namespace rt
