#include "geometry/shape.hpp"

namespace rt {

std::size_t memory_bytes(const Shape& shape) {
    if (const auto* mesh = std::get_if<Mesh>(&shape)) return sizeof(Shape) + memory_bytes(mesh->data());
    if (const auto* polygon = std::get_if<Polygon>(&shape))
        return sizeof(Shape) + polygon->vertices().size() * (sizeof(Vec3) + sizeof(Vec2));
    if (const auto* instance = std::get_if<Instance>(&shape)) return sizeof(Shape) + memory_bytes(instance->base());
    if (const auto* csg = std::get_if<Csg>(&shape))
        return sizeof(Shape) + memory_bytes(*csg->left().shape) + memory_bytes(*csg->right().shape);
    return sizeof(Shape);
}

bool moves(const Shape& shape) {
    if (const auto* sphere = std::get_if<Sphere>(&shape)) return sphere->moves();
    if (const auto* instance = std::get_if<Instance>(&shape)) return moves(instance->base());
    if (const auto* csg = std::get_if<Csg>(&shape)) return moves(*csg->left().shape) || moves(*csg->right().shape);
    return false;
}

}  // namespace rt
