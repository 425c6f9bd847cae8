// STUDENT COPY of solutions/ch08_refraction.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 08 exercises: refraction (book §8, course §9.7). Declared in
// common/shading/optics.hpp.
#include "core/exercise.hpp"
#include "shading/optics.hpp"

#include <cmath>

// @helpers
// Your #includes and helper functions, if any (inside namespace rt { ... } to use the
// library's names unqualified). ./lab exercises keeps these lines like an exercise body.
// @end

namespace rt {

bool refract(const Vec3& d, const Vec3& n, Real n_from, Real n_to, Vec3& t) {
    RT_STUDENT_EXERCISE(8, 1);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 8.1 | refract | book §8.1
    throw NotImplemented("exercise 8.1 (refract) is not done yet: see book §8.1");
    // @end
}

Real schlick(Real cosine, Real ior) {
    RT_STUDENT_EXERCISE(8, 2);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 8.2 | schlick | book §8.2
    throw NotImplemented("exercise 8.2 (schlick) is not done yet: see book §8.2");
    // @end
}

Color beer(const Color& attenuation, Real distance) {
    RT_STUDENT_EXERCISE(8, 3);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 8.3 | beer | book §8.3
    throw NotImplemented("exercise 8.3 (beer) is not done yet: see book §8.3");
    // @end
}

}  // namespace rt
