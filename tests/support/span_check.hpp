#pragma once
// What the CSG tests share (tests/test_ch13.cpp, tests/test_library_parts.cpp): span lists
// written as (in, out) pairs of t, and read back as such.
#include "geometry/shape.hpp"

#include <initializer_list>
#include <memory>
#include <utility>
#include <vector>

namespace rt::test {

using Pairs = std::vector<std::pair<Real, Real>>;

// Spans from (in, out) pairs; the ends are tagged in `primitive` with side*100 + 2*k (+1 for
// the out end), to check which operand's record ends a result span.
inline SpanList span_list(std::initializer_list<std::pair<Real, Real>> pairs, int side = 0) {
    SpanList s;
    std::uint32_t k = 0;
    for (auto [a, b] : pairs) {
        Span x;
        x.in.t = a;
        x.in.primitive = std::uint32_t(side) * 100 + 2 * k;
        x.out.t = b;
        x.out.primitive = std::uint32_t(side) * 100 + 2 * k + 1;
        s.push_back(x);
        ++k;
    }
    return s;
}

inline Pairs ts(const SpanList& s) {
    Pairs out;
    for (const Span& x : s) out.push_back({x.in.t, x.out.t});
    return out;
}

inline std::shared_ptr<const Shape> share(Shape s) {
    return std::make_shared<const Shape>(std::move(s));
}

}  // namespace rt::test
