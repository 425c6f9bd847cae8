#include "accel/course_bvh.hpp"

#include "accel/tree_depth.hpp"

#include "core/flat_bvh.hpp"
#include "core/hit_rounding.hpp"
#include "core/traversal_count.hpp"

#include <algorithm>
#include <numeric>

namespace rt {

BvhBuilder::BvhBuilder(std::vector<Box> boxes) : boxes_(std::move(boxes)) {
    centres_.reserve(boxes_.size());
    for (const Box& b : boxes_) centres_.push_back((b.min + b.max) * Real(0.5));
    nodes_.reserve(boxes_.size());
}

BvhRef BvhBuilder::add_node(BvhRef left, BvhRef right) {
    CourseBvhNode n{box(left), left, right};
    n.box.expand(box(right));
    nodes_.push_back(n);
    return BvhRef(nodes_.size() - 1);
}

namespace {

// The SAH tree of core/flat_bvh.hpp, one primitive a leaf, in the course's node form.
BvhRef from_flat(BvhBuilder& b, const FlatBvh& flat, std::uint32_t at) {
    const BvhNode& n = flat.nodes[at];
    if (n.leaf()) return b.primitive(flat.items[n.first]);
    const BvhRef left = from_flat(b, flat, n.first);
    const BvhRef right = from_flat(b, flat, n.first + 1);
    return b.add_node(left, right);
}

}  // namespace

Bvh::Bvh(const SurfaceList& surfaces, BvhBuild how) : primitives_(primitives_of(surfaces)) {
    if (primitives_.empty()) return;
    primitive_boxes_.reserve(primitives_.size());
    for (const Primitive& p : primitives_) primitive_boxes_.push_back(rt::bounding_box(surfaces, p));
    BvhBuilder builder(primitive_boxes_);
    std::vector<std::uint32_t> order(primitives_.size());
    std::iota(order.begin(), order.end(), 0u);
    switch (how) {
        case BvhBuild::sorted:
            root_ = build_sorted(builder, order, 0);
            break;
        case BvhBuild::midpoint:
            root_ = build_midpoint(builder, order, 0);
            break;
        case BvhBuild::sah:
            root_ = from_flat(builder, build_bvh(primitive_boxes_, 1), 0);
            break;
    }
    nodes_ = builder.take_nodes();
    // The exercises build with the primitives' own boxes; the search tests each node's box
    // grown by the rounding of the hits inside it (core/box.hpp), like every structure.
    for (CourseBvhNode& n : nodes_) n.box = grown_by_rounding(n.box);
}

const CourseBvhNode& Bvh::node(BvhRef ref) const {
    ++traversal_tally.nodes;
    return nodes_[ref];
}

Box Bvh::box(BvhRef ref) const {
    if (ref == kNone) return Box{};
    return is_primitive(ref) ? primitive_boxes_[ref & ~kPrimitiveBit] : nodes_[ref].box;
}

bool Bvh::hit_primitive(const SurfaceList& surfaces, BvhRef ref, const Ray& ray, Interval interval,
                        HitRecord& best) const {
    ++traversal_tally.items;
    return hit_closer(surfaces, primitives_[ref & ~kPrimitiveBit], ray, interval, best);
}

bool Bvh::hit(const SurfaceList& surfaces, const Ray& ray, Interval interval, HitRecord& rec) const {
    if (root_ == kNone) return false;
    HitRecord best = no_hit_before(interval.max);
    if (!hit_node(surfaces, root_, ray, interval, best)) return false;
    rec = best;
    return true;
}

bool Bvh::occluded(const SurfaceList& surfaces, const Ray& ray, Interval interval) const {
    if (root_ == kNone) return false;
    // Any hit will do, so no order and no recursion: a stack of what is left to look at.
    std::vector<BvhRef> stack{root_};
    while (!stack.empty()) {
        const BvhRef ref = stack.back();
        stack.pop_back();
        if (is_primitive(ref)) {
            ++traversal_tally.items;
            if (rt::occluded(surfaces, primitives_[ref & ~kPrimitiveBit], ray, interval)) return true;
            continue;
        }
        const CourseBvhNode& n = node(ref);
        if (!hit_box(n.box, ray, interval)) continue;
        stack.push_back(n.right);
        stack.push_back(n.left);
    }
    return false;
}

int Bvh::depth() const {
    if (root_ == kNone || is_primitive(root_)) return 0;
    const auto is_leaf = [&](BvhRef ref) { return is_primitive(ref); };
    const auto children = [&](BvhRef ref) { return std::pair{nodes_[ref].left, nodes_[ref].right}; };
    return tree_depth(root_, is_leaf, children);
}

}  // namespace rt
