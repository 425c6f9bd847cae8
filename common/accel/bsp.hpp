#pragma once
// The binary space partitioning tree (course §9.9.4, book §12): space cut in two by an
// axis-aligned plane, each half cut again, down to leaves that list primitives. Like the
// grid it divides space, not the objects: a primitive that crosses a plane is listed on both
// sides. Like the BVH it adapts to where the objects are. Searched by the course's
// four-case recursion (exercise 12.1); built by cycling the axes and cutting each cell at
// its middle (exercise 12.2) or where the surface-area heuristic says (library code).
#include "accel/primitive.hpp"

#include <span>
#include <vector>

namespace rt {

// @book bsp-node
// A node. An inner node cuts its cell by the plane where coordinate `axis` equals `split`:
// `left` holds what lies below the plane, `right` what lies above. A leaf lists the
// primitives items[first .. last) of its tree.
struct BspNode {
    static constexpr int kLeaf = 3;
    int axis = kLeaf;  // 0, 1, 2: x, y, z; kLeaf: a leaf
    Real split = 0;
    std::uint32_t left = 0, right = 0;  // inner: the children's indices; leaf: first and last item

    bool leaf() const { return axis == kLeaf; }
};
// @book-end

using BspRef = std::uint32_t;  // a node's index

// @book bsp-builder
// What a build works with: the primitives' boxes, the nodes and leaf lists made so far, and
// the rules that end it.
class BspBuilder {
public:
    BspBuilder(std::vector<Box> boxes, Real pad, int max_depth, std::size_t leaf_size);

    std::size_t primitives() const { return boxes_.size(); }
    const Box& box(std::uint32_t p) const { return boxes_[p]; }
    int max_depth() const { return max_depth_; }
    std::size_t leaf_size() const { return leaf_size_; }  // lists this short are not cut
    Real pad() const { return pad_; }

    // Sorts items to the sides of the plane coordinate[axis] = split. A primitive goes
    // below if its box reaches below split + 2 pad, above if it reaches above split - 2 pad:
    // one that crosses the plane, or comes within 2 pad of it, goes to both (book §12.3).
    void sort(std::span<const std::uint32_t> items, int axis, Real split, std::vector<std::uint32_t>& below,
              std::vector<std::uint32_t>& above) const;
    BspRef add_leaf(std::span<const std::uint32_t> items);
    BspRef add_inner(int axis, Real split, BspRef left, BspRef right);

    std::vector<BspNode> take_nodes() { return std::move(nodes_); }
    std::vector<std::uint32_t> take_items() { return std::move(items_); }

private:
    std::vector<Box> boxes_;
    Real pad_;
    int max_depth_;
    std::size_t leaf_size_;
    std::vector<BspNode> nodes_;
    std::vector<std::uint32_t> items_;
};

// The lower and upper part of a cell cut at coordinate[axis] = split.
inline Box below_plane(Box cell, int axis, Real split) {
    cell.max[axis] = split;
    return cell;
}
inline Box above_plane(Box cell, int axis, Real split) {
    cell.min[axis] = split;
    return cell;
}

// Exercise 12.2: the course's build. Cut the cell at its middle along axis depth % 3 and
// build each half from the items sorted to it (sort()), one level deeper, in its half of
// the cell: below the plane on the left, above on the right. A list of at most leaf_size()
// items, or one at depth max_depth(), is a leaf. A cut that sends more than half the items
// to both sides (more than 1.5 n listed from n) is not made: the next axis is tried, and
// after all three, a leaf. The tests demand the tree itself: each node's axis and plane,
// which primitives lie under each side, the leaves and the depth. The numbering of the
// nodes is free, and so is the way of halving: the plane is the cell's middle to within two
// units in the last place of its coordinates ((min + max)/2 and min + (max - min)/2 both
// pass), and exactly 0 for a cell symmetric about 0, where every way gives 0.
BspRef build_midpoint(BspBuilder& builder, std::span<const std::uint32_t> items, const Box& cell, int depth);
// @book-end

// The surface-area-heuristic build: the plane of least expected cost (a node visit plus the
// primitives tested on each side, weighted by the chance a ray through the cell meets that
// side), if it beats a leaf; the planes tried are just outside every box's faces, or, for
// long lists, the 31 between 32 equal bins per axis. Library code (bsp.cpp).
BspRef build_sah(BspBuilder& builder, std::span<const std::uint32_t> items, const Box& cell, int depth);

enum class BspBuild { midpoint, sah };

class Bsp {
public:
    Bsp(const SurfaceList& surfaces, BspBuild how, std::size_t leaf_size = 2);

    // The closest hit in the interval; rec is left alone if there is none.
    bool hit(const SurfaceList& surfaces, const Ray& ray, Interval interval, HitRecord& rec) const;
    bool occluded(const SurfaceList& surfaces, const Ray& ray, Interval interval) const;
    Box bounding_box() const { return bounds_; }
    // The part of the interval the tree is searched over: its end clipped to the tree's box
    // grown by the pad, its start kept; false if the ray misses that box (or the tree is empty).
    bool reach(const Ray& ray, Interval& interval) const;

    // @book bsp-search
    // Exercise 12.1: the course's four cases. Searches the subtree `ref` for the closest hit
    // in the interval (the part of the ray the search has reached this node with), keeping
    // it in best; true if it found one. The near side is the side of the plane where the
    // part starts; a part that starts exactly on the plane may take either side (both parts
    // below reach the slack past the plane, so the hits are the same). A ray that does not
    // move towards the plane (it moves away, or runs along it: d = +0 or -0), or reaches it
    // only after the part ends (t - slack > interval.max), searches the near side alone,
    // over the whole part. Otherwise the near side over [min, min(max, t + slack)] and, only
    // if that found nothing, the far side over [max(min, t - slack), max]. The tests demand
    // brute force's hit, and the nodes and primitives these cases visit (traversal_tally):
    // a search that finds the right hit with more work fails them.
    bool hit_node(const SurfaceList& surfaces, BspRef ref, const Ray& ray, Interval interval, HitRecord& best) const;

    // Tests a leaf's primitives over the interval, keeping a closer hit in best.
    bool hit_leaf(const SurfaceList& surfaces, const BspNode& leaf, const Ray& ray, Interval interval,
                  HitRecord& best) const;
    // How far along the ray the plane of an inner node may be misjudged by rounding: the
    // pad in space, divided by how fast the ray moves along the axis (book §12.3). Hits up
    // to this far past the plane still count on the near side.
    Real slack(const Ray& ray, int axis) const { return pad_ / std::abs(ray.direction[axis]); }

    BspRef root() const { return root_; }
    const BspNode& node(BspRef ref) const;  // counts the visit
    // @book-end
    std::span<const std::uint32_t> items(const BspNode& leaf) const {
        return std::span<const std::uint32_t>(items_).subspan(leaf.left, leaf.right - leaf.left);
    }
    const Primitive& primitive(std::uint32_t p) const { return primitives_[p]; }

    Real pad() const { return pad_; }
    std::size_t node_count() const { return nodes_.size(); }
    std::size_t primitive_count() const { return primitives_.size(); }
    std::size_t entries() const { return items_.size(); }  // primitives listed, summed over leaves
    std::size_t memory_bytes() const {
        return nodes_.size() * sizeof(BspNode) + items_.size() * sizeof(std::uint32_t) +
               primitives_.size() * sizeof(Primitive);
    }
    int depth() const;

private:
    bool occluded_node(const SurfaceList& surfaces, BspRef ref, const Ray& ray, Interval part, Interval interval) const;

    std::vector<Primitive> primitives_;
    Box bounds_;
    Real pad_ = 0;
    std::vector<BspNode> nodes_;
    std::vector<std::uint32_t> items_;
    BspRef root_ = kNone;
};

}  // namespace rt
