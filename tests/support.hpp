#pragma once
// Helpers shared by the unit tests.
#include "core/box.hpp"
#include "core/interval.hpp"
#include "core/ray.hpp"
#include "core/real.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <limits>
#include <ostream>
#include <string>

// What a failed check prints is what the student debugs with, so it prints values in full.
namespace doctest {

// Vectors by value, "(1, 2, 3)", not "{?}".
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

// Arrays by value, "{1, 2}" (chapter 04's projection axes), not "{?}".
template <class T, std::size_t N>
struct StringMaker<std::array<T, N>> {
    static String convert(const std::array<T, N>& a) {
        String s = "{";
        for (std::size_t i = 0; i < N; ++i) {
            if (i) s += ", ";
            s += toString(a[i]);
        }
        return s + "}";
    }
};

// A name as its text: doctest prints a const char* as the pointer (0x5559fa03e251) unless
// the whole program is built with DOCTEST_CONFIG_TREAT_CHAR_STAR_AS_STRING.
template <>
struct StringMaker<const char*> {
    static String convert(const char* s) { return s ? String("\"") + s + "\"" : String("{null}"); }
};
template <>
struct StringMaker<char*> {
    static String convert(const char* s) { return StringMaker<const char*>::convert(s); }
};

// The inputs of a ray query, so that a failure in a loop over random rays says which ray.
template <>
struct StringMaker<rt::Ray> {
    static String convert(const rt::Ray& r) {
        String s = "{origin " + toString(r.origin) + ", direction " + toString(r.direction);
        if (r.time != 0) s += ", time " + toString(r.time);
        return s + "}";
    }
};
template <>
struct StringMaker<rt::Interval> {
    static String convert(const rt::Interval& iv) { return "[" + toString(iv.min) + ", " + toString(iv.max) + "]"; }
};
template <>
struct StringMaker<rt::Box> {
    static String convert(const rt::Box& b) { return "{min " + toString(b.min) + ", max " + toString(b.max) + "}"; }
};

}  // namespace doctest

namespace rt::test {

// doctest prints a floating-point value with its string stream's default 6 significant
// digits, so a t that differs in the 7th prints as "CHECK( 1 == 1 )". Every value it prints
// goes through that one stream (thread-local, reused, the tests' thread): set it once, before
// any test runs, to the digits that tell any two doubles apart (17; a float needs 9).
inline const bool kFullPrecision = [] {
    doctest::detail::tlssPush()->precision(std::numeric_limits<double>::max_digits10);
    doctest::detail::tlssPop();
    return true;
}();

}  // namespace rt::test

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
