// STUDENT COPY of solutions/ch05_ray_tracing_program.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 05 exercises: the ray tracing program (book §5, course §9.4-9.4.1). Declared in
// common/accel/surface_list.hpp and common/shading/shading.hpp.
#include "accel/surface_list.hpp"
#include "core/exercise.hpp"
#include "shading/shading.hpp"

#include <cmath>

// @helpers
// Your #includes and helper functions, if any (inside namespace rt { ... } to use the
// library's names unqualified). ./lab exercises keeps these lines like an exercise body.
// @end

namespace rt {

bool SurfaceList::hit(const Ray& ray, Interval interval, HitRecord& rec) const {
    RT_STUDENT_EXERCISE(5, 1);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 5.1 | SurfaceList::hit | book §5.2
    throw NotImplemented("exercise 5.1 (SurfaceList::hit) is not done yet: see book §5.2");
    // @end
}

Color lambert(const Color& diffuse, const Color& light, const Vec3& n, const Vec3& l) {
    RT_STUDENT_EXERCISE(5, 2);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 5.2 | lambert | book §5.4
    throw NotImplemented("exercise 5.2 (lambert) is not done yet: see book §5.4");
    // @end
}

Color blinn_phong_highlight(const Color& specular, float exponent, const Color& light, const Vec3& n, const Vec3& l,
                            const Vec3& v) {
    RT_STUDENT_EXERCISE(5, 3);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 5.3 | blinn_phong_highlight | book §5.4
    throw NotImplemented("exercise 5.3 (blinn_phong_highlight) is not done yet: see book §5.4");
    // @end
}

}  // namespace rt
