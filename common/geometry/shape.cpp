#include "geometry/shape.hpp"

namespace rt {

std::size_t memory_bytes(const Shape& shape) {
    return sizeof(Shape) +
           match(
               shape, [](const Sphere&) -> std::size_t { return 0; }, [](const Triangle&) -> std::size_t { return 0; },
               [](const Polygon& p) -> std::size_t { return p.vertices().size() * (sizeof(Vec3) + sizeof(Vec2)); },
               [](const Mesh& m) { return memory_bytes(m.data()); },
               [](const Instance& in) { return memory_bytes(in.base()); },
               [](const Cuboid&) -> std::size_t { return 0; },
               [](const Csg& c) { return memory_bytes(*c.left().shape) + memory_bytes(*c.right().shape); });
}

bool moves(const Shape& shape) {
    return match(
        shape, [](const Sphere& s) { return s.moves(); }, [](const Triangle&) { return false; },
        [](const Polygon&) { return false; }, [](const Mesh&) { return false; },
        [](const Instance& in) { return moves(in.base()); }, [](const Cuboid&) { return false; },
        [](const Csg& c) { return moves(*c.left().shape) || moves(*c.right().shape); });
}

}  // namespace rt
