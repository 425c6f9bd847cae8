// The statistical image test of tools/ztest.hpp (book §14.6) on numbers whose verdict is
// known: Šidák's level, Student's t, and the floor for rounding-sized differences.
#include "support.hpp"
#include "ztest.hpp"

#include <cmath>
#include <vector>

using namespace rt;

TEST_SUITE("common") {
TEST_CASE("the statistical test: Sidak's level, Student's t, and a verdict on known numbers") {
    // Sidak: 1 - (1 - alpha)^(1/N); for small alpha close to alpha / N.
    CHECK(stat::sidak(0.01, 1) == doctest::Approx(0.01));
    CHECK(stat::sidak(0.01, 10000) == doctest::Approx(1.005e-6).epsilon(1e-3));
    // Student's t against closed forms: with 1 degree of freedom P(|T| > t) = (2/pi) atan(1/t),
    // with 2 it is 2 / (s (s + t)), s = sqrt(2 + t^2); far into the tails too.
    for (double t : {0.3, 1.0, 4.0, 1e3, 1e6}) {
        CAPTURE(t);
        CHECK(stat::t_tail(t, 1) == doctest::Approx(2 / std::numbers::pi * std::atan(1 / t)).epsilon(1e-12));
        const double s = std::sqrt(2 + t * t);
        CHECK(stat::t_tail(t, 2) == doctest::Approx(2 / (s * (s + t))).epsilon(1e-12));
    }
    // Table quantiles: t(0.975; 60) = 2.000298, t(0.995; 30) = 2.749996, t(0.9995; 10) = 4.586894.
    CHECK(stat::t_tail(2.000298, 60) == doctest::Approx(0.05).epsilon(1e-5));
    CHECK(stat::t_tail(2.749996, 30) == doctest::Approx(0.01).epsilon(1e-5));
    CHECK(stat::t_tail(4.586894, 10) == doctest::Approx(0.001).epsilon(1e-5));
    // Far more degrees of freedom: the normal distribution's tails, P(|Z| > 3.290527) = 0.001.
    CHECK(stat::t_tail(3.290527, 1e6) == doctest::Approx(0.001).epsilon(1e-4));
    CHECK(stat::t_tail(3.290527, 1e12) == doctest::Approx(0.001).epsilon(1e-5));
    // The same deviation is far likelier under t: why a variance from 64 renders needs it.
    CHECK(stat::t_tail(4.87, 63) > 5 * stat::t_tail(4.87, 1e9));

    // An average of 4 renders of variance 4 has standard deviation 1. Variance taken as exact
    // (0 renders): the normal's P(|Z| > 1.959964) = 0.05.
    CHECK(stat::p_value(1.959964, 4, 0, 4, 0, 0) == doctest::Approx(0.05).epsilon(1e-5));
    CHECK(stat::p_value(-3.290527, 4, 0, 4, 0, 0) == doctest::Approx(0.001).epsilon(1e-5));
    // Estimated from 11 renders: t with 10 degrees of freedom, t(0.975; 10) = 2.228139.
    CHECK(stat::p_value(2.228139, 4, 0, 4, 0, 11) == doctest::Approx(0.05).epsilon(1e-5));
    // A floor as large as the noise: spread 2, and 10 (2 / 1)^2 = 40 degrees of freedom,
    // t(0.975; 40) = 2.021075.
    CHECK(stat::p_value(2.021075 * std::sqrt(2.0), 4, 0, 4, 1, 11) == doctest::Approx(0.05).epsilon(1e-5));
    // Nothing varies: equal is a pass, any difference a failure; NaN is a failure.
    CHECK(stat::p_value(5, 8, 5, 0, 0, 64) == 1);
    CHECK(stat::p_value(5.001, 8, 5, 0, 0, 64) == 0);
    CHECK(stat::p_value(std::nan(""), 8, 5, 1, 0.004, 64) == 0);
    // One list's variance about the mean of 4.
    const stat::MeanVar mv = stat::mean_var({{1, 5}, {2, 5}, {3, 5}, {4, 5}});
    CHECK(mv.mean[0] == doctest::Approx(2.5));
    CHECK(mv.var[0] == doctest::Approx((1.5 * 1.5 * 2 + 0.5 * 0.5 * 2) / 3));
    CHECK(mv.var[1] == 0);

    // 1000 values: the image fails on the smallest p alone, however few values are off.
    const stat::MeanVar ref{std::vector<double>(1000, 0.5), std::vector<double>(1000, 1e-3)};
    std::vector<std::vector<double>> renders(8, std::vector<double>(1000, 0.5));
    for (std::size_t k = 0; k < renders.size(); ++k) renders[k][3] += k % 2 ? 0.02 : -0.02;  // noise, mean kept
    stat::Verdict v = stat::compare(renders, ref, 0.01, 0, 64);
    CHECK(v.level == doctest::Approx(stat::sidak(0.01, 1000)));
    CHECK(v.failed == 0);
    CHECK(v.pass());
    // Off by 4.6 standard deviations of the average: p = 2.1e-5 under t with 63 degrees of
    // freedom, above the level of 1.0e-5, but 4.2e-6 for the normal z-test, below it.
    for (auto& r : renders) r[17] = 0.5 + 4.6 * std::sqrt(1e-3 / 8);
    v = stat::compare(renders, ref, 0.01, 0, 64);
    CHECK(v.failed == 0);
    CHECK(v.smallest_p > v.level);
    CHECK(v.pass());
    CHECK_FALSE(stat::compare(renders, ref, 0.01, 0, 0).pass());
    // One value far off: the image fails, as it would with many.
    for (auto& r : renders) r[18] = 0.6;
    v = stat::compare(renders, ref, 0.01, 0, 64);
    CHECK(v.failed == 1);
    CHECK(v.smallest_p < v.level);
    CHECK_FALSE(v.pass());
    // A floor of 0.04 makes that 0.1 rounding-sized: it passes.
    CHECK(stat::compare(renders, ref, 0.01, 0.04, 64).pass());
}
}  // TEST_SUITE("common")
