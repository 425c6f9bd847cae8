#include "core/wide_bvh.hpp"

#include <limits>

namespace rt {

namespace {

float half_area(const BvhNode& n) {
    const float x = n.hi[0] - n.lo[0], y = n.hi[1] - n.lo[1], z = n.hi[2] - n.lo[2];
    return x * y + y * z + z * x;
}

// Fills wide node `at` from binary inner node `b`: its two children, then, while there is
// room, the inner child of largest area replaced by its own two children (the one most rays
// would open next).
template <int W>
void fill(const FlatBvh& bvh, std::uint32_t b, WideBvh<W>& out, std::uint32_t at) {
    std::uint32_t kids[W] = {bvh.nodes[b].first, bvh.nodes[b].first + 1};
    int n = 2;
    while (n < W) {
        int open = -1;
        for (int i = 0; i < n; ++i)
            if (!bvh.nodes[kids[i]].leaf() &&
                (open < 0 || half_area(bvh.nodes[kids[i]]) > half_area(bvh.nodes[kids[open]])))
                open = i;
        if (open < 0) break;
        const std::uint32_t first = bvh.nodes[kids[open]].first;
        kids[open] = first;
        kids[n++] = first + 1;
    }
    WideNode<W> node{};
    constexpr float inf = std::numeric_limits<float>::infinity();
    for (int c = 0; c < W; ++c)
        for (int a = 0; a < 3; ++a) {
            node.lo[a][c] = c < n ? bvh.nodes[kids[c]].lo[a] : inf;
            node.hi[a][c] = c < n ? bvh.nodes[kids[c]].hi[a] : -inf;
        }
    for (int c = 0; c < n; ++c) {
        const BvhNode& k = bvh.nodes[kids[c]];
        if (k.leaf()) {
            node.first[c] = k.first;
            node.count[c] = k.count;
        } else {
            node.first[c] = std::uint32_t(out.nodes.size());
            out.nodes.emplace_back();
            fill(bvh, kids[c], out, node.first[c]);
        }
    }
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
    out.nodes.reserve(bvh.nodes.size() / (W - 1) + 1);
    out.nodes.emplace_back();
    fill(bvh, 0, out, 0);
    return out;
}

template WideBvh<4> collapse<4>(const FlatBvh&);
template WideBvh<8> collapse<8>(const FlatBvh&);

}  // namespace rt
