#pragma once
// Helpers shared by the unit tests.
#include "core/real.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

// Failed checks print vectors by value, "(1, 2, 3)", not "{?}".
namespace doctest {
template <glm::length_t L, class T, glm::qualifier Q>
struct StringMaker<glm::vec<L, T, Q>> {
    static String convert(const glm::vec<L, T, Q>& v) {
        String s = "(";
        for (glm::length_t i = 0; i < L; ++i) {
            if (i) s += ", ";
            s += toString(v[i]);
        }
        return s + ")";
    }
};
}  // namespace doctest

// Inside a loop over many cases: the first failure is checked in full (with whatever the loop
// CAPTUREs), later ones are only counted, so a wrong exercise prints a few lines, not
// thousands. Check the count after the loop: CHECK(failures == 0).
#define RT_CHECK_FIRST(failures, ...)                                \
    do {                                                             \
        if (!(__VA_ARGS__) && (failures)++ == 0) CHECK(__VA_ARGS__); \
    } while (0)

namespace rt::test {

// Machine epsilon of the configured Real: tolerances are stated in multiples of it so that
// one test states the same claim for float and double.
inline constexpr Real kEps = std::numeric_limits<Real>::epsilon();

inline Real rel_error(long double got, long double want) {
    return Real(std::fabs(got - want) / std::max(std::fabs(want), 1.0L));
}

}  // namespace rt::test
