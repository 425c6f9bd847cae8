#pragma once
// What the CSG tests share (tests/test_ch13.cpp, tests/test_geometry.cpp): span lists
// written as (in, out) pairs of t, and read back as such.
#include "geometry/shape.hpp"

#include <doctest/doctest.h>

#include <initializer_list>
#include <limits>
#include <memory>
#include <sstream>
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

// A failed CHECK(ts(x) == Pairs{...}) prints both lists of spans, "{[0, 2], [2, 2]}", each t
// with every digit it has (max_digits10): two ends that differ in the last place must not
// both print as 2.
namespace doctest {
template <>
struct StringMaker<rt::test::Pairs> {
    static String convert(const rt::test::Pairs& pairs) {
        std::ostringstream out;
        out.precision(std::numeric_limits<rt::Real>::max_digits10);
        out << "{";
        for (std::size_t k = 0; k < pairs.size(); ++k)
            out << (k ? ", [" : "[") << pairs[k].first << ", " << pairs[k].second << "]";
        out << "}";
        return out.str().c_str();
    }
};
}  // namespace doctest
