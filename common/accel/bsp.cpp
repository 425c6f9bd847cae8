#include "accel/bsp.hpp"

#include "accel/tree_depth.hpp"
#include "core/limits.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace rt {

BspBuilder::BspBuilder(std::vector<Box> boxes, Real pad, int max_depth, std::size_t leaf_size)
    : boxes_(std::move(boxes)), pad_(pad), max_depth_(max_depth), leaf_size_(leaf_size) {}

void BspBuilder::sort(std::span<const std::uint32_t> items, int axis, Real split, std::vector<std::uint32_t>& below,
                      std::vector<std::uint32_t>& above) const {
    below.clear();
    above.clear();
    for (std::uint32_t p : items) {
        if (boxes_[p].min[axis] <= split + 2 * pad_) below.push_back(p);
        if (boxes_[p].max[axis] >= split - 2 * pad_) above.push_back(p);
    }
}

BspRef BspBuilder::add_leaf(std::span<const std::uint32_t> items) {
    // A build may list a primitive in many leaves (a pile of long primitives all crossing):
    // past the limit it is refused rather than allowed to eat the machine.
    if (!limits::contains(limits::bsp_entries, double(items_.size() + items.size())))
        throw std::invalid_argument("bsp: too many primitives cross its planes (" +
                                    std::string(limits::bsp_entries.name) + " " +
                                    limits::describe(limits::bsp_entries) + "); use a BVH (--accel fast)");
    BspNode n;
    n.left = std::uint32_t(items_.size());
    items_.insert(items_.end(), items.begin(), items.end());
    n.right = std::uint32_t(items_.size());
    nodes_.push_back(n);
    return BspRef(nodes_.size() - 1);
}

BspRef BspBuilder::add_inner(int axis, Real split, BspRef left, BspRef right) {
    nodes_.push_back(BspNode{axis, split, left, right});
    return BspRef(nodes_.size() - 1);
}

namespace {

// The surface-area heuristic's price of a cell's split, in units of one node visit: the
// visit, plus the primitives tested on each side times the chance that a ray through the
// cell meets that side (the ratio of surface areas). A side left empty earns a bonus: a ray
// through it costs nothing. A primitive test costs about as much as kIntersect visits.
constexpr Real kTraverse = 1, kIntersect = 16, kEmptyBonus = Real(0.5);
// Lists longer than this try the 31 planes between 32 equal bins per axis; shorter ones try a
// plane just outside every box's faces, which is exact and finds the empty space around an
// object however small it is in its cell.
constexpr std::size_t kExactBelow = 512;
constexpr int kBins = 32;

Real half_area(const Vec3& e) {
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

struct Split {
    Real cost;
    int axis = -1;
    Real at = 0;
};

void consider(Split& best, const Box& cell, int axis, Real at, std::size_t below, std::size_t above) {
    if (!(at > cell.min[axis] && at < cell.max[axis])) return;
    const Vec3 extent = cell.max - cell.min;
    Vec3 e_below = extent, e_above = extent;
    e_below[axis] = at - cell.min[axis];
    e_above[axis] = cell.max[axis] - at;
    const Real bonus = (below == 0 || above == 0) ? kEmptyBonus : 0;
    const Real cost = kTraverse + kIntersect * (1 - bonus) *
                                      (half_area(e_below) * Real(below) + half_area(e_above) * Real(above)) /
                                      half_area(extent);
    if (cost < best.cost) best = Split{cost, axis, at};
}

// Every box's faces along the axis, the plane put 3 pads outside each so that the box falls
// wholly on one side of it (BspBuilder::sort lists a box within 2 pads on both sides).
void exact_planes(const BspBuilder& b, std::span<const std::uint32_t> items, const Box& cell, int axis, Split& best) {
    std::vector<Real> lo, hi;
    lo.reserve(items.size());
    hi.reserve(items.size());
    for (std::uint32_t p : items) {
        lo.push_back(b.box(p).min[axis]);
        hi.push_back(b.box(p).max[axis]);
    }
    std::sort(lo.begin(), lo.end());
    std::sort(hi.begin(), hi.end());
    const Real pad = b.pad();
    const auto count = [&](Real at) {
        const auto below = std::size_t(std::upper_bound(lo.begin(), lo.end(), at + 2 * pad) - lo.begin());
        const auto above = std::size_t(hi.end() - std::lower_bound(hi.begin(), hi.end(), at - 2 * pad));
        consider(best, cell, axis, at, below, above);
    };
    for (Real x : lo) count(x - 3 * pad);
    for (Real x : hi) count(x + 3 * pad);
}

// The 31 planes between 32 equal bins: how many boxes start and end in each bin; a plane between bins has
// below it every box that starts before it, above it every box that ends after it.
void binned_planes(const BspBuilder& b, std::span<const std::uint32_t> items, const Box& cell, int axis, Split& best) {
    std::array<std::size_t, kBins> starts{}, ends{};
    const Real scale = Real(kBins) / (cell.max[axis] - cell.min[axis]);
    const auto bin = [&](Real x) { return std::size_t(std::clamp(int((x - cell.min[axis]) * scale), 0, kBins - 1)); };
    for (std::uint32_t p : items) {
        ++starts[bin(b.box(p).min[axis])];
        ++ends[bin(b.box(p).max[axis])];
    }
    std::size_t below = 0, above = items.size();
    for (int k = 1; k < kBins; ++k) {
        below += starts[std::size_t(k - 1)];
        above -= ends[std::size_t(k - 1)];
        consider(best, cell, axis, cell.min[axis] + (cell.max[axis] - cell.min[axis]) * Real(k) / Real(kBins), below,
                 above);
    }
}

}  // namespace

BspRef build_sah(BspBuilder& b, std::span<const std::uint32_t> items, const Box& cell, int depth) {
    const std::size_t n = items.size();
    if (n <= b.leaf_size() || depth >= b.max_depth()) return b.add_leaf(items);
    Split best{kIntersect * Real(n)};  // a leaf's cost: a split must beat it
    for (int axis = 0; axis < 3; ++axis) {
        if (!(cell.max[axis] > cell.min[axis])) continue;
        if (n < kExactBelow)
            exact_planes(b, items, cell, axis, best);
        else
            binned_planes(b, items, cell, axis, best);
    }
    if (best.axis < 0) return b.add_leaf(items);
    std::vector<std::uint32_t> below, above;
    b.sort(items, best.axis, best.at, below, above);
    if (below.size() == n && above.size() == n) return b.add_leaf(items);  // the pad put all on both
    const BspRef left = build_sah(b, below, below_plane(cell, best.axis, best.at), depth + 1);
    const BspRef right = build_sah(b, above, above_plane(cell, best.axis, best.at), depth + 1);
    return b.add_inner(best.axis, best.at, left, right);
}

Bsp::Bsp(const SurfaceList& surfaces, BspBuild how, std::size_t leaf_size) : primitives_(primitives_of(surfaces)) {
    if (primitives_.empty()) return;
    std::vector<Box> boxes;
    boxes.reserve(primitives_.size());
    for (const Primitive& p : primitives_) {
        boxes.push_back(rt::bounding_box(surfaces, p));
        bounds_.expand(boxes.back());
    }
    // The pad covers rounding in where a hit and a plane crossing are computed: 256 units in
    // the last place of the scene's largest coordinate (16 times a hit's alone, hit_rounding
    // in core/hit_rounding.hpp), and never less than 2^-20 of it. In float the first decides (3e-5 of
    // the size); in double the floor does (1e-6): far more than double's rounding needs, at
    // the price of a few more copies next to planes.
    const Vec3 reach = glm::max(glm::abs(bounds_.min), glm::abs(bounds_.max));
    const Vec3 extent = bounds_.max - bounds_.min;
    const Real size = std::max({reach.x, reach.y, reach.z, extent.x, extent.y, extent.z});
    pad_ = size * std::max(Real(256) * std::numeric_limits<Real>::epsilon(), Real(1) / Real(1 << 20));
    // pbrt's depth limit: deep enough for most trees, shallow enough that a pile of crossing
    // primitives cannot multiply the lists for ever. (Book §12.5: with 16 + 1.5 log2 N the
    // SAH tree tests a fifth of the primitives on a 10^5 terrain but takes ten times the
    // memory, and no less time.)
    const int max_depth = std::min(48, int(std::lround(8 + 1.3 * std::log2(double(primitives_.size())))));
    BspBuilder builder(std::move(boxes), pad_, max_depth, leaf_size);
    std::vector<std::uint32_t> all(primitives_.size());
    std::iota(all.begin(), all.end(), 0u);
    root_ = how == BspBuild::midpoint ? build_midpoint(builder, all, bounds_, 0) : build_sah(builder, all, bounds_, 0);
    nodes_ = builder.take_nodes();
    items_ = builder.take_items();
}

const BspNode& Bsp::node(BspRef ref) const {
    ++traversal_tally.nodes;
    return nodes_[ref];
}

bool Bsp::hit_leaf(const SurfaceList& surfaces, const BspNode& leaf, const Ray& ray, Interval interval,
                   HitRecord& best) const {
    bool found = false;
    for (std::uint32_t p : items(leaf)) {
        ++traversal_tally.items;
        if (hit_closer(surfaces, primitives_[p], ray, Interval{interval.min, std::min(interval.max, best.t)}, best))
            found = true;
    }
    return found;
}

bool Bsp::reach(const Ray& ray, Interval& interval) const {
    if (root_ == kNone) return false;
    // Clipped to the tree's box grown by the pad: the box is made of the primitives' boxes, so
    // a wall can lie in its face, and its hit is computed a rounding error in or out of it
    // (from close by at a grazing angle, about half the time; far from the origin, where that
    // error is a unit in the last place of the coordinates, on every ray that meets the wall
    // at the face). The near end is not clipped: the four cases hold for the whole line, and
    // a hit a rounding error before the box's face must count too.
    Interval inside = interval;
    const Box grown{bounds_.min - Vec3(pad_), bounds_.max + Vec3(pad_)};
    if (!clip_to_box(grown, ray, inside)) return false;
    interval.max = inside.max;
    return true;
}

bool Bsp::hit(const SurfaceList& surfaces, const Ray& ray, Interval interval, HitRecord& rec) const {
    HitRecord best = no_hit_before(interval.max);
    if (!reach(ray, interval) || !hit_node(surfaces, root_, ray, interval, best)) return false;
    rec = best;
    return true;
}

bool Bsp::occluded_node(const SurfaceList& surfaces, BspRef ref, const Ray& ray, Interval part,
                        Interval interval) const {
    // Any hit will do: the halves the part reaches, in any order, each primitive tested over
    // the whole interval.
    const BspNode& n = node(ref);
    if (n.leaf()) {
        for (std::uint32_t p : items(n)) {
            ++traversal_tally.items;
            if (rt::occluded(surfaces, primitives_[p], ray, interval)) return true;
        }
        return false;
    }
    const Real d = ray.direction[n.axis];
    const Real p = ray.origin[n.axis] + part.min * d;
    const bool starts_below = p < n.split || (p == n.split && d < 0);
    const BspRef near = starts_below ? n.left : n.right, far = starts_below ? n.right : n.left;
    if (starts_below ? !(d > 0) : !(d < 0)) return occluded_node(surfaces, near, ray, part, interval);
    const Real t = (n.split - ray.origin[n.axis]) / d, s = slack(ray, n.axis);
    if (occluded_node(surfaces, near, ray, Interval{part.min, std::min(part.max, t + s)}, interval)) return true;
    return t - s <= part.max &&
           occluded_node(surfaces, far, ray, Interval{std::max(part.min, t - s), part.max}, interval);
}

bool Bsp::occluded(const SurfaceList& surfaces, const Ray& ray, Interval interval) const {
    Interval part = interval;
    return reach(ray, part) && occluded_node(surfaces, root_, ray, part, interval);
}

int Bsp::depth() const {
    if (root_ == kNone) return 0;
    const auto is_leaf = [&](BspRef ref) { return nodes_[ref].leaf(); };
    const auto children = [&](BspRef ref) { return std::pair{nodes_[ref].left, nodes_[ref].right}; };
    return tree_depth(root_, is_leaf, children);
}

}  // namespace rt
