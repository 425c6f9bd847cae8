// STUDENT COPY of solutions/ch13_csg.cpp, made by tools/gen_exercises.cpp.
// Write your code between each "@exercise" line and its "@end", in place of the throw.
// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.
// Chapter 13 exercises: constructive solid geometry (book §13, course §9.10). Declared in
// common/geometry/csg.hpp.
#include "core/exercise.hpp"
#include "geometry/csg.hpp"

#include <algorithm>

namespace rt {

// @book combine
SpanList combine(CsgOp op, const SpanList& a, const SpanList& b) {
    // @exercise 13.1 | combine | book §13.2
    throw NotImplemented("exercise 13.1 (combine) is not done yet: see book §13.2");
    // @end
}
// @book-end

// @book mesh-spans
SpanList mesh_spans(const std::vector<HitRecord>& crossings, const Vec3& direction, Real same_t) {
    // @exercise 13.2 | mesh_spans | book §13.3
    throw NotImplemented("exercise 13.2 (mesh_spans) is not done yet: see book §13.3");
    // @end
}
// @book-end

}  // namespace rt
