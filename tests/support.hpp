#pragma once
// Helpers shared by the unit tests.
#include "core/real.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

namespace rt::test {

// Machine epsilon of the configured Real: tolerances are stated in multiples of it so that
// one test states the same claim for float and double.
inline constexpr Real kEps = std::numeric_limits<Real>::epsilon();

inline Real rel_error(long double got, long double want) {
    return Real(std::fabs(got - want) / std::max(std::fabs(want), 1.0L));
}

}  // namespace rt::test
