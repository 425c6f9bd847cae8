// STUDENT COPY of solutions/ch09_instancing.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 09 exercises: instancing (book §9, course §9.8). Declared in
// common/geometry/instance.hpp.
#include "core/exercise.hpp"
#include "geometry/instance.hpp"

namespace rt {

// @book object-ray
Ray object_ray(const Affine& to_object, const Ray& ray) {
    // @exercise 9.1 | object_ray | book §9.2
    throw NotImplemented("exercise 9.1 (object_ray) is not done yet: see book §9.2");
    // @end
}
// @book-end

// @book normal
Vec3 world_normal(const Affine& to_object, const Vec3& n) {
    // @exercise 9.2 | world_normal | book §9.3
    throw NotImplemented("exercise 9.2 (world_normal) is not done yet: see book §9.3");
    // @end
}
// @book-end

// @book box
Box transform_box(const Affine& to_world, const Box& box) {
    // @exercise 9.3 | transform_box | book §9.4
    throw NotImplemented("exercise 9.3 (transform_box) is not done yet: see book §9.4");
    // @end
}
// @book-end

}  // namespace rt
