#include "geometry/csg.hpp"

#include "geometry/limits.hpp"
#include "geometry/shape.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

namespace rt {

void drop_thin(SpanList& spans, Real thin, const Vec3& direction) {
    if (!(thin > 0) || spans.empty()) return;
    const Real length = glm::length(direction);
    SpanList kept;
    kept.reserve(spans.size());
    for (const Span& s : spans) {
        if ((s.out.t - s.in.t) * length < thin) continue;  // a sliver of solid
        if (!kept.empty() && (s.in.t - kept.back().out.t) * length < thin)
            kept.back().out = s.out;  // a sliver of air between two spans: one span
        else
            kept.push_back(s);
    }
    spans = std::move(kept);
}

Real default_thin(const Box& box) {
    const Vec3 size = box.max - box.min;
    const Real extent = std::max({size.x, size.y, size.z});
    return extent * std::max(Real(1e-6), 64 * std::numeric_limits<Real>::epsilon());
}

namespace {

// Does every edge of the mesh have exactly one partner running the other way? Then the
// triangles enclose a volume, with their counter-clockwise sides facing out.
bool closed(const MeshData& d) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;  // directed edge -> uses
    for (const auto& t : d.triangles)
        for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
    for (const auto& [edge, uses] : edges) {
        if (uses != 1) return false;
        const auto back = edges.find({edge.second, edge.first});
        if (back == edges.end() || back->second != 1) return false;
    }
    return true;
}

// Every other kind is one leaf, seen through instances.
std::uint32_t leaf_count(const Shape& shape) {
    using N = std::uint32_t;
    return match(
        shape, [](const Csg& c) { return c.leaves(); }, [](const Instance& in) { return leaf_count(in.base()); },
        [](const Sphere&) { return N(1); }, [](const Triangle&) { return N(1); }, [](const Polygon&) { return N(1); },
        [](const Mesh&) { return N(1); }, [](const Cuboid&) { return N(1); });
}

// The nearest CSG object inside a shape (itself, or under instances), if any.
const Csg* csg_in(const Shape& shape) {
    return match(
        shape, [](const Csg& c) -> const Csg* { return &c; }, [](const Instance& in) { return csg_in(in.base()); },
        [](const Sphere&) -> const Csg* { return nullptr; }, [](const Triangle&) -> const Csg* { return nullptr; },
        [](const Polygon&) -> const Csg* { return nullptr; }, [](const Mesh&) -> const Csg* { return nullptr; },
        [](const Cuboid&) -> const Csg* { return nullptr; });
}

// An operand's spans, owned by the CSG above: parts numbered from `first_leaf`, material
// the operand's where it set one and nothing below it did.
void operand_spans(const CsgOperand& operand, std::uint32_t first_leaf, const Ray& ray, bool flip, SpanList& out) {
    spans(*operand.shape, ray, out);
    for (Span& s : out)
        for (HitRecord* r : {&s.in, &s.out}) {
            r->part = r->part == kNone ? first_leaf : r->part + first_leaf;
            if (r->material == kNone) r->material = operand.material;
            // A subtracted solid's surface bounds the result from the other side.
            if (flip) r->normal = -r->normal, r->shading_normal = -r->shading_normal;
        }
}

SpanList sphere_spans(const Sphere& sphere, const Ray& ray) {
    const Sphere s = sphere.moves() ? sphere.at(ray.time) : sphere;  // where it is at the ray's time
    Real t0, t1;
    if (!sphere_roots(ray, s.center, s.radius, t0, t1)) return {};
    const SurfaceRef none{kNone, kNone};
    return {Span{record(s, ray, SphereHit{t0}, none), record(s, ray, SphereHit{t1}, none)}};
}

SpanList cuboid_spans(const Cuboid& box, const Ray& ray) {
    CuboidHit enter, leave;
    if (!cuboid_crossings(box, ray, enter, leave)) return {};
    const SurfaceRef none{kNone, kNone};
    return {Span{record(box, ray, enter, none), record(box, ray, leave, none)}};
}

SpanList mesh_spans(const Mesh& mesh, const Ray& ray) {
    const Interval line{-kInfinity, kInfinity};
    if (!might_hit(mesh.box(), ray, line)) return {};
    const MeshAccel& a = mesh.accel();
    std::vector<HitRecord> crossings;
    const RayShear shear(ray);
    for_each_leaf_entered(
        a.wide, WideRay<kMeshBvhWidth>(ray), line,
        [&](std::uint32_t b, std::uint32_t, Interval& iv) {
            for_each_hit(a.blocks[b], a.corners_of(b), shear, ray, iv,
                         [&](std::uint32_t index, const TriangleHit& h, const std::array<Vec3, 3>& c) {
                             crossings.push_back(record(mesh, ray, MeshHit{h, index, c}, SurfaceRef{kNone, kNone}));
                             return false;  // every crossing, not the first
                         });
        },
        [&](std::uint32_t b) { prefetch(a.blocks[b]); });
    // The brute-force order (t, then triangle), so the result does not depend on the tree.
    std::sort(crossings.begin(), crossings.end(), [](const HitRecord& x, const HitRecord& y) {
        return x.t != y.t ? x.t < y.t : x.primitive < y.primitive;
    });
    // Two triangles that share an edge put the same point at t's that differ by rounding:
    // a few units in the last place of the distances involved.
    const Box& b = mesh.box();
    const Real scale = glm::length(b.max - b.min) + glm::length(ray.origin - (b.min + b.max) / Real(2));
    const Real same_t = 256 * std::numeric_limits<Real>::epsilon() * scale / glm::length(ray.direction);
    return mesh_spans(crossings, ray.direction, same_t);
}

SpanList instance_spans(const Instance& instance, const Ray& ray) {
    SpanList local;
    spans(instance.base(), object_ray(instance.to_object(), ray), local);
    for (Span& s : local)
        for (HitRecord* r : {&s.in, &s.out})  // record() stamps who; keep the operand's own
            *r = record(instance, ray, InstanceHit{*r}, SurfaceRef{r->surface, r->material});
    return local;
}

SpanList csg_spans(const Csg& csg, const Ray& ray) {
    SpanList a, b;
    operand_spans(csg.left(), 0, ray, false, a);
    operand_spans(csg.right(), leaf_count(*csg.left().shape), ray, csg.op() == CsgOp::difference, b);
    SpanList result = combine(csg.op(), a, b);
    drop_thin(result, csg.thin(), ray.direction);
    return result;
}

}  // namespace

// Six times the volume a closed mesh encloses, positive when its triangles wind counter-
// clockwise seen from outside (the divergence theorem: a sum of signed tetrahedra from one
// point, here the first vertex, which keeps the products small).
double signed_volume6(const MeshData& mesh) {
    const glm::dvec3 o(mesh.positions.front());
    double sum = 0;
    for (const auto& t : mesh.triangles) {
        const glm::dvec3 a = glm::dvec3(mesh.positions[t[0]]) - o, b = glm::dvec3(mesh.positions[t[1]]) - o,
                         c = glm::dvec3(mesh.positions[t[2]]) - o;
        sum += glm::dot(a, glm::cross(b, c));
    }
    return sum;
}

std::string not_solid(const Shape& shape) {
    return match(
        shape, [](const Sphere&) { return std::string(); },
        [](const Triangle&) { return std::string("a triangle has no inside"); },
        [](const Polygon&) { return std::string("a polygon has no inside"); },
        [](const Mesh& m) -> std::string {
            if (!closed(m.data()))
                return "the mesh is not closed (an edge without exactly one partner running the other way)";
            // Its spans would come out reversed (every entry an exit): it would vanish from the result.
            if (!(signed_volume6(m.data()) > 0))
                return "the mesh is inside out (its triangles wind clockwise seen from outside: no volume inside)";
            return "";
        },
        [](const Instance& in) { return not_solid(in.base()); }, [](const Cuboid&) { return std::string(); },
        [](const Csg&) { return std::string(); });
}

void spans(const Shape& shape, const Ray& ray, SpanList& out) {
    out = match(
        shape, [&](const Sphere& s) { return sphere_spans(s, ray); },
        [&](const Cuboid& c) { return cuboid_spans(c, ray); }, [&](const Mesh& m) { return mesh_spans(m, ray); },
        [&](const Instance& in) { return instance_spans(in, ray); }, [&](const Csg& g) { return csg_spans(g, ray); },
        // Flat shapes have no inside: the Csg constructor refuses them as operands (not_solid).
        [](const Triangle&) { return SpanList(); }, [](const Polygon&) { return SpanList(); });
}

Csg::Csg(CsgOp op, CsgOperand left, CsgOperand right, Real thin)
    : op_(op), left_(std::move(left)), right_(std::move(right)) {
    for (const CsgOperand* o : {&left_, &right_}) {
        if (!o->shape) throw std::invalid_argument("csg: an operand is missing");
        const std::string why = not_solid(*o->shape);
        if (!why.empty())
            throw std::invalid_argument("csg: operand " +
                                        (o->name.empty() ? std::string(shape_kind(*o->shape)) : "\"" + o->name + "\"") +
                                        " is not a closed solid: " + why);
    }
    const Box a = rt::bounding_box(*left_.shape), b = rt::bounding_box(*right_.shape);
    switch (op_) {
        case CsgOp::union_of:
            box_ = a;
            box_.expand(b);
            break;
        case CsgOp::intersection:
            box_ = Box{glm::max(a.min, b.min), glm::min(a.max, b.max)};
            if (box_.empty())
                throw std::invalid_argument("csg: the intersection is empty (its operands' boxes do not overlap)");
            break;
        case CsgOp::difference:  // never larger than what it is cut from
            box_ = a;
            break;
    }
    thin_ = thin < 0 ? default_thin(box_) : thin;
    left_leaves_ = leaf_count(*left_.shape);
    right_leaves_ = leaf_count(*right_.shape);
    // Checked at every node, so the count (never over the limit below) cannot wrap round.
    if (!limits::contains(limits::csg_leaves, double(left_leaves_) + double(right_leaves_)))
        throw std::invalid_argument("csg: " +
                                    limits::refuse(limits::csg_leaves, double(left_leaves_) + double(right_leaves_)));
}

std::string Csg::describe(std::uint32_t part, bool subtracted) const {
    const bool on_left = part < left_leaves_;
    const CsgOperand& o = on_left ? left_ : right_;
    if (!on_left) part -= left_leaves_;
    // The right side of a difference is subtracted; subtracted twice, it is added back.
    const bool flipped = subtracted != (!on_left && op_ == CsgOp::difference);
    if (const Csg* inner = csg_in(*o.shape)) return inner->describe(part, flipped);
    const std::string kind = shape_kind(*o.shape);
    return (o.name.empty() ? kind : o.name + " (" + kind + ")") + (flipped ? ", subtracted" : "");
}

std::string describe_part(const Shape& shape, std::uint32_t part) {
    const Csg* csg = csg_in(shape);
    return csg && part < csg->leaves() ? csg->describe(part) : "";
}

bool hit(const Csg& csg, const Ray& ray, Interval interval, CsgHit& result) {
    if (!might_hit(csg.box(), ray, interval)) return false;
    const SpanList list = csg_spans(csg, ray);
    for (const Span& s : list)
        for (const HitRecord* r : {&s.in, &s.out})
            if (interval.contains(r->t)) {
                result = CsgHit{*r};
                return true;
            }
    return false;
}

HitRecord record(const Csg&, const Ray&, const CsgHit& h, SurfaceRef who) {
    HitRecord rec = h.local;
    rec.surface = who.surface;
    if (rec.material == kNone) rec.material = who.material;
    return rec;
}

}  // namespace rt
