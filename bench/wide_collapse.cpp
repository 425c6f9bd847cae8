// How a mesh's binary SAH tree becomes an 8-wide one (book §10.5): the lab's cost-based
// collapse against the obvious greedy rule, counted on real meshes. Exact counts, no times.
//
//   build/release/bin/bench_wide_collapse [--book OUT.md] MESH.obj ...
//
// For each mesh: the binary tree as the mesh builds it (build_bvh over the triangles' boxes,
// four to a leaf, leaves counted in blocks), then
//   greedy: each wide node starts from a binary node's two children and opens its largest
//           inner child (by surface area) until it has eight or none is left to open;
//   cost:   collapse<8>, the lab's (Ylitie, Karras and Laine 2017), as the mesh holds it.
// Printed: wide nodes, how many have 2, 3, ... 8 children, the mean, and the depth in wide
// levels against the binary tree's. --book writes the sentence §10.5 quotes for the first mesh.
#include "core/flat_bvh.hpp"
#include "core/wide_bvh.hpp"
#include "geometry/mesh.hpp"
#include "io/obj.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

using namespace rt;

namespace {

constexpr int kWidth = 8;

struct Shape {
    std::size_t nodes = 0;
    std::array<std::size_t, kWidth + 1> with{};  // with[c]: wide nodes of c children
    int depth = 0;                               // wide levels from the root to the deepest leaf
    double mean() const {
        std::size_t sum = 0;
        for (int c = 0; c <= kWidth; ++c) sum += c * with[c];
        return nodes ? double(sum) / double(nodes) : 0;
    }
};

float half_area(const BvhNode& n) {
    const float x = n.hi[0] - n.lo[0], y = n.hi[1] - n.lo[1], z = n.hi[2] - n.lo[2];
    return x * y + y * z + z * x;
}

// The greedy rule, from binary node b (an inner node), at wide level `level`.
void greedy(const FlatBvh& bvh, std::uint32_t b, int level, Shape& s) {
    std::vector<std::uint32_t> kids = {bvh.nodes[b].first, bvh.nodes[b].first + 1};
    while (kids.size() < kWidth) {
        auto best = kids.end();
        for (auto it = kids.begin(); it != kids.end(); ++it)
            if (!bvh.nodes[*it].leaf() &&
                (best == kids.end() || half_area(bvh.nodes[*it]) > half_area(bvh.nodes[*best])))
                best = it;
        if (best == kids.end()) break;
        const std::uint32_t open = *best;
        *best = bvh.nodes[open].first;
        kids.push_back(bvh.nodes[open].first + 1);
    }
    ++s.nodes;
    ++s.with[kids.size()];
    s.depth = std::max(s.depth, level);
    for (std::uint32_t k : kids)
        if (!bvh.nodes[k].leaf()) greedy(bvh, k, level + 1, s);
}

// The lab's collapsed tree as it is stored.
void walk(const WideBvh<kWidth>& wide, std::uint32_t n, int level, Shape& s) {
    const WideNode<kWidth>& node = wide.nodes[n];
    int c = 0;
    for (std::uint32_t ref : node.child)
        if (ref != 0) ++c;
    ++s.nodes;
    ++s.with[c];
    s.depth = std::max(s.depth, level);
    for (std::uint32_t ref : node.child)
        if (ref != 0 && !is_leaf(ref)) walk(wide, ref, level + 1, s);
}

std::string thousands(std::size_t v) {
    std::string s = std::to_string(v);
    for (int i = int(s.size()) - 3; i > 0; i -= 3) s.insert(std::size_t(i), ",");
    return s;
}

void print(const char* rule, const Shape& s) {
    std::printf("  %-7s %8zu", rule, s.nodes);
    for (int c = 2; c <= kWidth; ++c) std::printf(" %6zu", s.with[c]);
    std::printf(" %6.2f %6d\n", s.mean(), s.depth);
}

}  // namespace

int main(int argc, char** argv) {
    std::string book;
    std::vector<std::string> meshes;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--book" && i + 1 < argc)
            book = argv[++i];
        else if (!a.empty() && a[0] == '-') {
            std::fprintf(stderr, "bench_wide_collapse: unknown option '%s' (expected --book OUT.md)\n", a.c_str());
            return 2;
        } else
            meshes.push_back(a);
    }
    if (meshes.empty()) {
        std::fprintf(stderr, "usage: bench_wide_collapse [--book OUT.md] MESH.obj ...\n");
        return 2;
    }
    std::printf("binary SAH tree (4 triangles a leaf) collapsed to %d children a node; exact counts\n", kWidth);
    for (const std::string& path : meshes) {
        try {
            const Mesh mesh(load_obj(path));
            const MeshData& d = mesh.data();
            std::vector<Box> boxes(d.triangles.size());
            for (std::size_t k = 0; k < boxes.size(); ++k)
                for (std::uint32_t v : d.triangles[k]) boxes[k].expand(d.positions[v]);
            const FlatBvh bvh = build_bvh(boxes, 4, 4);  // as the mesh builds it (geometry/mesh.cpp)
            if (bvh.nodes.empty() || bvh.nodes[0].leaf()) {
                std::fprintf(stderr, "bench_wide_collapse: %s: one leaf holds the whole mesh\n", path.c_str());
                return 2;
            }
            Shape g, c;
            greedy(bvh, 0, 1, g);
            walk(mesh.accel().wide, 0, 1, c);
            const std::string name = std::filesystem::path(path).stem().string();
            std::printf("\n%s: %zu triangles, binary tree %zu nodes, depth %d\n", name.c_str(), d.triangles.size(),
                        bvh.nodes.size(), bvh.depth);
            std::printf("  rule       nodes");
            for (int k = 2; k <= kWidth; ++k) std::printf("  %d kid", k);
            std::printf("   mean  depth\n");
            print("greedy", g);
            print("cost", c);
            if (!book.empty() && &path == &meshes.front()) {
                FILE* f = std::fopen(book.c_str(), "w");
                if (!f) {
                    std::fprintf(stderr, "bench_wide_collapse: cannot write %s\n", book.c_str());
                    return 2;
                }
                std::fprintf(f,
                             "On `%s`, %s of the greedy rule's %s wide nodes have two "
                             "children and %s three; the cost-based collapse makes %s nodes of %.1f children on "
                             "average, and the tree is %d levels deep where the binary one is %d.\n",
                             std::filesystem::path(path).filename().string().c_str(), thousands(g.with[2]).c_str(),
                             thousands(g.nodes).c_str(), thousands(g.with[3]).c_str(), thousands(c.nodes).c_str(),
                             c.mean(), c.depth, bvh.depth);
                std::fclose(f);
            }
        } catch (const std::exception& e) {
            std::fprintf(stderr, "bench_wide_collapse: %s\n", e.what());
            return 2;
        }
    }
    return 0;
}
