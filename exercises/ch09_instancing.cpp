// STUDENT COPY of solutions/ch09_instancing.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 09 exercises: instancing (book §9, course §9.8). Declared in
// common/geometry/instance.hpp.
#include "core/exercise.hpp"
#include "geometry/instance.hpp"

// @helpers
// Your #includes and helper functions, if any (inside namespace rt { ... } to use the
// library's names unqualified). ./lab exercises keeps these lines like an exercise body.
// @end

namespace rt {

Ray object_ray(const Affine& to_object, const Ray& ray) {
    RT_STUDENT_EXERCISE(9, 1);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 9.1 | object_ray | book §9.2
    throw NotImplemented("exercise 9.1 (object_ray) is not done yet: see book §9.2");
    // @end
}

Vec3 world_normal(const Affine& to_object, const Vec3& n) {
    RT_STUDENT_EXERCISE(9, 2);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 9.2 | world_normal | book §9.3
    throw NotImplemented("exercise 9.2 (world_normal) is not done yet: see book §9.3");
    // @end
}

Box transform_box(const Affine& to_world, const Box& box) {
    RT_STUDENT_EXERCISE(9, 3);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 9.3 | transform_box | book §9.4
    throw NotImplemented("exercise 9.3 (transform_box) is not done yet: see book §9.4");
    // @end
}

}  // namespace rt
