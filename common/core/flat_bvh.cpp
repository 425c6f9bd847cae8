#include "core/flat_bvh.hpp"
#include "core/float_round.hpp"
#include "core/hit_rounding.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

#include <tbb/parallel_invoke.h>

namespace rt {

namespace {

Real half_area(const Box& b) {
    const Vec3 e = b.max - b.min;
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

constexpr int kBins = 16;

// The build splits into parallel tasks in its top levels, for sides this large: enough tasks
// for a machine's cores, and each big enough to be worth one.
constexpr int kParallelLevels = 6;
constexpr std::uint32_t kParallelItems = 4096;

struct Builder {
    std::span<const Box> boxes;
    std::vector<Vec3> centres;
    FlatBvh& out;
    unsigned max_leaf;
    unsigned lanes;

    // What testing n items costs, in item tests: items go through in passes of `lanes`.
    Real cost(std::uint32_t n) const { return Real((n + lanes - 1) / lanes); }

    void leaf(BvhNode& node, std::uint32_t begin, std::uint32_t end) {
        node.first = begin;
        node.count = end - begin;
    }

    // Where to split items [begin, end) with the surface-area heuristic, or end for "make a
    // leaf": the expected cost of a split, 1 box test plus each side's items weighted by
    // the chance (area ratio) that a ray through the parent meets that side, against the
    // cost of testing all items here.
    std::uint32_t sah_split(std::uint32_t begin, std::uint32_t end, const Box& bounds, const Box& centre_bounds) {
        const std::uint32_t n = end - begin;
        int best_axis = -1, best_bin = 0;
        Real best_cost = kInfinity;
        for (int a = 0; a < 3; ++a) {
            const Real lo = centre_bounds.min[a], extent = centre_bounds.max[a] - lo;
            if (!(extent > 0)) continue;
            std::array<Box, kBins> bin_box{};
            std::array<std::uint32_t, kBins> bin_count{};
            const Real scale = kBins / extent;
            for (std::uint32_t k = begin; k < end; ++k) {
                const std::uint32_t item = out.items[k];
                const int b = std::min(kBins - 1, int((centres[item][a] - lo) * scale));
                bin_box[b].expand(boxes[item]);
                ++bin_count[b];
            }
            // Sweep from the right to know each right side, then from the left.
            std::array<Real, kBins> right_area{};
            std::array<std::uint32_t, kBins> right_count{};
            Box right;
            std::uint32_t count = 0;
            for (int b = kBins - 1; b > 0; --b) {
                right.expand(bin_box[b]);
                count += bin_count[b];
                right_area[b] = count ? half_area(right) : 0;
                right_count[b] = count;
            }
            Box left;
            count = 0;
            for (int b = 0; b < kBins - 1; ++b) {
                left.expand(bin_box[b]);
                count += bin_count[b];
                if (count == 0 || right_count[b + 1] == 0) continue;
                const Real split = half_area(left) * cost(count) + right_area[b + 1] * cost(right_count[b + 1]);
                if (split < best_cost) {
                    best_cost = split;
                    best_axis = a;
                    best_bin = b;
                }
            }
        }
        if (best_axis < 0) return end;  // every centre in one place: no plane separates them
        const Real parent = half_area(bounds);
        const Real split_cost = 1 + (parent > 0 ? best_cost / parent : cost(n));
        if (n <= max_leaf && split_cost >= cost(n)) return end;
        const Real lo = centre_bounds.min[best_axis];
        const Real scale = kBins / (centre_bounds.max[best_axis] - lo);
        const auto mid = std::partition(out.items.begin() + begin, out.items.begin() + end, [&](std::uint32_t item) {
            return std::min(kBins - 1, int((centres[item][best_axis] - lo) * scale)) <= best_bin;
        });
        return std::uint32_t(mid - out.items.begin());
    }

    // Half the items on each side of the median centre along the widest axis: what a build
    // falls back to near the depth limit, and for items whose centres coincide.
    std::uint32_t median_split(std::uint32_t begin, std::uint32_t end, const Box& centre_bounds) {
        const Vec3 e = centre_bounds.max - centre_bounds.min;
        const int a = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
        const std::uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(out.items.begin() + begin, out.items.begin() + mid, out.items.begin() + end,
                         [&](std::uint32_t i, std::uint32_t j) { return centres[i][a] < centres[j][a]; });
        return mid;
    }

    // Builds the subtree of items [begin, end) whose root is nodes[at]; its descendants are
    // appended to `nodes` depth first, each pair of children side by side.
    void build(std::vector<BvhNode>& nodes, int& deepest, std::uint32_t at, std::uint32_t begin, std::uint32_t end,
               int depth) {
        deepest = std::max(deepest, depth);
        Box bounds, centre_bounds;
        for (std::uint32_t k = begin; k < end; ++k) {
            bounds.expand(boxes[out.items[k]]);
            centre_bounds.expand(centres[out.items[k]]);
        }
        // Stored grown by the rounding of the hits inside (the heuristic weighs the boxes as
        // they are), and in float bounds containing the Real ones: a box only grows.
        const Box search = grown_by_rounding(bounds);
        for (int a = 0; a < 3; ++a) {
            nodes[at].lo[a] = float_below(search.min[a]);
            nodes[at].hi[a] = float_above(search.max[a]);
        }
        const std::uint32_t n = end - begin;
        if (n == 1) return leaf(nodes[at], begin, end);
        // Near the depth limit only halving is allowed: bit_width(n) more levels reach one item.
        const bool must_halve = depth + int(std::bit_width(n)) >= kMaxBvhDepth;
        std::uint32_t mid =
            must_halve ? median_split(begin, end, centre_bounds) : sah_split(begin, end, bounds, centre_bounds);
        if (mid == end) {
            if (n <= max_leaf) return leaf(nodes[at], begin, end);
            mid = median_split(begin, end, centre_bounds);
        }
        const auto left = std::uint32_t(nodes.size());
        nodes.push_back({});
        nodes.push_back({});
        nodes[at].first = left;
        nodes[at].count = 0;
        if (depth < kParallelLevels && std::min(mid - begin, end - mid) >= kParallelItems) {
            // The two sides in parallel, each into its own array, then laid out as the serial
            // build lays them out: the same tree, byte for byte, whatever the thread count.
            std::vector<BvhNode> sides[2];
            int side_depth[2] = {depth + 1, depth + 1};
            const auto side = [&](int k, std::uint32_t from, std::uint32_t to) {
                sides[k].reserve(2 * std::size_t(to - from));
                sides[k].push_back({});
                build(sides[k], side_depth[k], 0, from, to, depth + 1);
            };
            tbb::parallel_invoke([&] { side(0, begin, mid); }, [&] { side(1, mid, end); });
            for (int k = 0; k < 2; ++k) {
                deepest = std::max(deepest, side_depth[k]);
                // sides[k][0] goes to slot left + k, sides[k][i >= 1] to nodes.size() + i - 1.
                const auto shift = std::uint32_t(nodes.size() - 1);
                const auto moved = [&](BvhNode node) {
                    if (!node.leaf()) node.first += shift;
                    return node;
                };
                nodes[left + std::uint32_t(k)] = moved(sides[k][0]);
                for (std::size_t i = 1; i < sides[k].size(); ++i) nodes.push_back(moved(sides[k][i]));
            }
            return;
        }
        build(nodes, deepest, left, begin, mid, depth + 1);
        build(nodes, deepest, left + 1, mid, end, depth + 1);
    }
};

}  // namespace

FlatBvh build_bvh(std::span<const Box> boxes, unsigned max_leaf, unsigned lanes) {
    FlatBvh bvh;
    if (boxes.empty()) return bvh;
    Builder b{boxes, {}, bvh, std::max(1u, max_leaf), std::max(1u, lanes)};
    b.centres.reserve(boxes.size());
    for (const Box& box : boxes) b.centres.push_back((box.min + box.max) * Real(0.5));
    bvh.items.resize(boxes.size());
    for (std::uint32_t k = 0; k < bvh.items.size(); ++k) bvh.items[k] = k;
    bvh.nodes.reserve(2 * boxes.size());
    bvh.nodes.push_back({});
    b.build(bvh.nodes, bvh.depth, 0, 0, std::uint32_t(boxes.size()), 0);
    bvh.nodes.shrink_to_fit();
    return bvh;
}

}  // namespace rt
