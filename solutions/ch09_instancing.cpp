// Chapter 09 exercises: instancing (book §9, course §9.8). Declared in
// common/geometry/instance.hpp.
#include "core/exercise.hpp"
#include "geometry/instance.hpp"

namespace rt {

// @book object-ray
Ray object_ray(const Affine& to_object, const Ray& ray) {
    // @exercise 9.1 | object_ray | book §9.2
    // A point moves with the translation, a direction does not; and d keeps the length
    // M^-1 gives it, so the t of a hit is the same in both spaces.
    return Ray{to_object.point(ray.origin), to_object.vector(ray.direction), ray.time};
    // @end
}
// @book-end

// @book normal
Vec3 world_normal(const Affine& to_object, const Vec3& n) {
    // @exercise 9.2 | world_normal | book §9.3
    return unit_vector(glm::transpose(to_object.m) * n);
    // @end
}
// @book-end

// @book box
Box transform_box(const Affine& to_world, const Box& box) {
    // @exercise 9.3 | transform_box | book §9.4
    Box result;
    for (int corner = 0; corner < 8; ++corner)
        result.expand(to_world.point(Vec3(corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                                          corner & 4 ? box.max.z : box.min.z)));
    return result;
    // @end
}
// @book-end

}  // namespace rt
