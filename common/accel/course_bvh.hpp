#pragma once
// The bounding volume hierarchy as the course builds it (course §9.9.2, book §10.2-10.4):
// a binary tree of boxes whose leaves are the scene's primitives, built by the course's
// two recipes (exercises 10.2 and 10.3) or the surface-area heuristic, and searched by the
// course's recursive hit (exercise 10.4). Like the course's bvh-node it is a surface: it
// answers the same queries (hit, occluded, bounding_box). The renderer's default is the
// faster form of the same idea, accel/two_level_bvh.hpp; both return the same hits.
#include "accel/primitive.hpp"

#include <span>
#include <vector>

namespace rt {

// Exercise 10.1: does the ray meet the box for some t in the interval? The slab test with
// the reciprocal trick (course §9.9.1), the far distance padded by a few ulps so rounding
// never loses a hit; a NaN (a ray lying in a slab's plane) must not reject. The box and the
// interval are closed: a ray that only touches a face, an edge or a corner, or starts on
// one, or lies in a face's plane, meets the box, with +0 and -0 direction components alike;
// a ray through an edge or corner at t meets it in an interval that ends or starts at t.
// Never a hit: the empty box, a NaN end of the interval, a box wholly outside the interval.
bool hit_box(const Box& box, const Ray& ray, Interval interval);

// @book bvh-node
// A child: a node's index, or (top bit set) a primitive's.
using BvhRef = std::uint32_t;
inline constexpr BvhRef kPrimitiveBit = 1u << 31;
inline bool is_primitive(BvhRef ref) {
    return (ref & kPrimitiveBit) != 0;
}

struct CourseBvhNode {
    Box box;
    BvhRef left, right;
};
// @book-end

// What a build works with: the primitives' boxes and centres, and the nodes made so far.
class BvhBuilder {
public:
    explicit BvhBuilder(std::vector<Box> boxes);

    // The reference a leaf uses for primitive p.
    BvhRef primitive(std::uint32_t p) const { return p | kPrimitiveBit; }
    const Box& box(BvhRef ref) const { return is_primitive(ref) ? boxes_[ref & ~kPrimitiveBit] : nodes_[ref].box; }
    const Vec3& centre(std::uint32_t p) const { return centres_[p]; }
    // A new node over two children; its box is the union of theirs.
    BvhRef add_node(BvhRef left, BvhRef right);

    std::size_t primitives() const { return boxes_.size(); }
    std::vector<CourseBvhNode> take_nodes() { return std::move(nodes_); }

private:
    std::vector<Box> boxes_;
    std::vector<Vec3> centres_;
    std::vector<CourseBvhNode> nodes_;
};

// Exercise 10.2: the course's first build. Sort the primitives by their centre along `axis`,
// put the first half in the left subtree and the rest in the right, the children split
// along the next axis. One primitive is its own reference (no node). For an odd count
// either half may take the odd one; the tree is balanced either way (depth ceil(log2 n)).
BvhRef build_sorted(BvhBuilder& builder, std::span<std::uint32_t> primitives, int axis);

// Exercise 10.3: the course's second build. Split at the midpoint of the primitives' box
// along `axis`, each side to one child (which side goes left is yours to choose); when
// every centre falls on one side, split the list in half instead (how it is ordered first
// is yours too), so the recursion always ends. Every primitive ends in exactly one leaf.
BvhRef build_midpoint(BvhBuilder& builder, std::span<std::uint32_t> primitives, int axis);

enum class BvhBuild { sorted, midpoint, sah };

class Bvh {
public:
    Bvh(const SurfaceList& surfaces, BvhBuild how);

    // The closest hit in the interval; rec is left alone if there is none.
    bool hit(const SurfaceList& surfaces, const Ray& ray, Interval interval, HitRecord& rec) const;
    bool occluded(const SurfaceList& surfaces, const Ray& ray, Interval interval) const;
    Box bounding_box() const { return box(root_); }

    // @book bvh-search
    // Exercise 10.4: the course's recursive search below `ref`. `best` holds the best hit
    // so far (its t is the interval's far end); hit_primitive() keeps a closer one there.
    bool hit_node(const SurfaceList& surfaces, BvhRef ref, const Ray& ray, Interval interval, HitRecord& best) const;

    // Tests primitive reference `ref` (a leaf) and keeps its hit in best if closer.
    bool hit_primitive(const SurfaceList& surfaces, BvhRef ref, const Ray& ray, Interval interval,
                       HitRecord& best) const;
    const CourseBvhNode& node(BvhRef ref) const;  // counts the box test it is read for
    // @book-end
    Box box(BvhRef ref) const;

    std::size_t node_count() const { return nodes_.size(); }
    std::size_t primitive_count() const { return primitives_.size(); }
    std::size_t memory_bytes() const {
        return nodes_.size() * sizeof(CourseBvhNode) + primitives_.size() * sizeof(Primitive);
    }
    int depth() const;

private:
    std::vector<Primitive> primitives_;
    std::vector<Box> primitive_boxes_;
    std::vector<CourseBvhNode> nodes_;
    BvhRef root_ = kNone;
};

}  // namespace rt
