// STUDENT COPY of solutions/ch13_csg.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 13 exercises: constructive solid geometry (book §13, course §9.10). Declared in
// common/geometry/csg.hpp.
#include "core/exercise.hpp"
#include "geometry/csg.hpp"

#include <algorithm>

// @helpers
// Your #includes and helper functions, if any (inside namespace rt { ... } to use the
// library's names unqualified). ./lab exercises keeps these lines like an exercise body.
// @end

namespace rt {

SpanList combine(CsgOp op, const SpanList& a, const SpanList& b) {
    RT_STUDENT_EXERCISE(13, 1);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 13.1 | combine | book §13.2
    throw NotImplemented("exercise 13.1 (combine) is not done yet: see book §13.2");
    // @end
}

SpanList mesh_spans(const std::vector<HitRecord>& crossings, const Vec3& direction, Real same_t) {
    RT_STUDENT_EXERCISE(13, 2);  // tells the grader this ran (core/exercise.hpp)
    // @exercise 13.2 | mesh_spans | book §13.3
    throw NotImplemented("exercise 13.2 (mesh_spans) is not done yet: see book §13.3");
    // @end
}

}  // namespace rt
