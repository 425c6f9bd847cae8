#pragma once
// Constructive solid geometry (book §13, course §9.10). A CSG object combines two closed
// shapes by union, intersection or difference without building the result: along each ray
// it finds every stretch inside each operand, combines those lists as sets, and reports the
// first end of a stretch in the query's interval. combine and mesh_spans are the chapter 13
// exercises (solutions/ch13_csg.cpp); the rest is here and in csg.cpp.
#include "core/box.hpp"
#include "core/interval.hpp"
#include "core/names.hpp"
#include "core/ray.hpp"
#include "geometry/hit_record.hpp"

#include <memory>
#include <string>
#include <vector>

namespace rt {

struct Shape;  // geometry/shape.hpp: an operand may be any closed shape, another CSG too

// A stretch of the ray's line inside a solid, from the crossing where the ray enters it to
// the one where it leaves, each a whole record whose normal points out of the solid.
struct Span {
    HitRecord in, out;
};
// Spans along one line: sorted by t and disjoint.
using SpanList = std::vector<Span>;

enum class CsgOp { union_of, intersection, difference };
inline constexpr auto kCsgOpNames = names_of<CsgOp>({"union", "intersection", "difference"});

// Exercise 13.1: the spans inside `a op b`, from the spans inside a and inside b. Walk the
// ends of both lists in order of t, entries before exits at equal t (across both lists,
// and within one: two spans of one list may touch), counting how deep the ray is inside
// each operand; a result span starts at the end where the operation becomes true and ends
// at the end where it becomes false, each a whole record, copied. Free, and accepted by the
// tests either way: which of two ends of one kind at one t comes first (so which record a
// result span takes there), and whether a span of no thickness is kept for drop_thin or
// dropped here.
SpanList combine(CsgOp op, const SpanList& a, const SpanList& b);

// Exercise 13.2: the spans inside a closed mesh, from every crossing of its surface along the
// line (sorted by t, then triangle) and the ray's direction. Crossings whose t differ by at
// most `same_t` are one crossing: a ray through an edge or a vertex meets every triangle
// there. A group takes each next crossing within same_t of its first one, or of the one
// before (either: the tests accept both), and counts by the sign of its sum, +1 for each
// crossing that enters (direction . normal < 0), -1 for each that leaves. The ray is inside
// or outside, never deeper: a group that enters while inside, or leaves while outside,
// changes nothing. A span runs from the first entering crossing of the group that opens it
// to the first leaving crossing of the group that closes it.
SpanList mesh_spans(const std::vector<HitRecord>& crossings, const Vec3& direction, Real same_t);

// Drops the spans, and then closes the gaps between spans, that are thinner than `thin`: a
// length in the space of the ray given (t times |direction|), which for a CSG object under a
// transform is the object's own space. Two solids that share a face meet there with rounding
// error, which would otherwise leave slivers of one inside or outside the other.
void drop_thin(SpanList& spans, Real thin, const Vec3& direction);

// One side of a CSG object: a closed shape and, optionally, its own material and a name for
// --pick. kNone: the material of the CSG object (or of the operand above it).
struct CsgOperand {
    std::shared_ptr<const Shape> shape;
    MaterialId material = kNone;
    std::string name = {};
};

// A hit on a CSG object: the record of the operand's surface it came from.
struct CsgHit {
    HitRecord local;
};

class Csg {
public:
    using Hit = CsgHit;

    // `thin` < 0 takes default_thin(box). Throws std::invalid_argument for an operand that is
    // not a closed solid (a triangle, a polygon, an open mesh, an instance of one of these),
    // or an intersection whose operands' boxes do not overlap (it would be empty).
    Csg(CsgOp op, CsgOperand left, CsgOperand right, Real thin = -1);

    CsgOp op() const { return op_; }
    const CsgOperand& left() const { return left_; }
    const CsgOperand& right() const { return right_; }
    Real thin() const { return thin_; }
    const Box& box() const { return box_; }
    // The operands in the whole tree that are not CSG objects themselves; HitRecord::part
    // numbers them left to right.
    std::uint32_t leaves() const { return left_leaves_ + right_leaves_; }
    // Which operand `part` is, for --pick: its name and kind, and "subtracted" if its surface
    // bounds the result from the other side (its normals flipped).
    std::string describe(std::uint32_t part) const { return describe(part, false); }

private:
    std::string describe(std::uint32_t part, bool subtracted) const;

    CsgOp op_;
    CsgOperand left_, right_;
    Real thin_;
    Box box_;
    std::uint32_t left_leaves_, right_leaves_;
};

// The default thickness below which spans are dropped: a millionth of the object's size
// (in float, 64 units in the last place of it).
Real default_thin(const Box& box);

// Which operand `part` of the CSG object in `shape` (itself or under instances) is; empty if
// the shape holds no CSG object.
std::string describe_part(const Shape& shape, std::uint32_t part);

// Why a shape cannot be a CSG operand (empty if it can): only closed solids have an inside.
std::string not_solid(const Shape& shape);

// Every span of a closed shape along the ray's whole line (t from -inf to inf); records are
// owned by no surface, their material kNone unless a CSG operand set one.
void spans(const Shape& shape, const Ray& ray, SpanList& out);

bool hit(const Csg& csg, const Ray& ray, Interval interval, CsgHit& result);
HitRecord record(const Csg& csg, const Ray& ray, const CsgHit& h, SurfaceRef who = {});
inline Box bounding_box(const Csg& csg) {
    return csg.box();
}

}  // namespace rt
