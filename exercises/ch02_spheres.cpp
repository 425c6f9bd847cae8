// STUDENT COPY of solutions/ch02_spheres.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 02 exercises: ray-sphere intersection (book §2, course §9.3.1). Declared in
// common/geometry/sphere.hpp.
#include "core/exercise.hpp"
#include "geometry/sphere.hpp"

#include <cmath>

// @helpers
// Your #includes and helper functions, if any (inside namespace rt { ... } to use the
// library's names unqualified). ./lab exercises keeps these lines like an exercise body.
// @end

namespace rt {

bool sphere_roots_textbook(const Ray& ray, const Vec3& center, Real radius, Real& t_near, Real& t_far) {
    RT_STUDENT_EXERCISE(2, 1);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 2.1 | sphere_roots_textbook | book §2.2
    throw NotImplemented("exercise 2.1 (sphere_roots_textbook) is not done yet: see book §2.2");
    // @end
}

bool sphere_roots(const Ray& ray, const Vec3& center, Real radius, Real& t_near, Real& t_far) {
    RT_STUDENT_EXERCISE(2, 2);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 2.2 | sphere_roots | book §2.3
    throw NotImplemented("exercise 2.2 (sphere_roots) is not done yet: see book §2.3");
    // @end
}

bool hit(const Sphere& sphere, const Ray& ray, Interval interval, SphereHit& result) {
    RT_STUDENT_EXERCISE(2, 3);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 2.3 | hit(Sphere) | book §2.4
    throw NotImplemented("exercise 2.3 (hit(Sphere)) is not done yet: see book §2.4");
    // @end
}

}  // namespace rt
