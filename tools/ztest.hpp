#pragma once
// The statistical image test of the noisy chapters (book §14.6), after Mitsuba 3's render
// tests: is the image a sampler makes, on average, the reference's? The reference holds, per
// pixel-channel, a converged mean and the variance of one render at the test's settings
// (estimated from a known number of renders of the reference solution). The test averages
// M renders of the student's code (M seeds) and gives each pixel-channel a t-test of that
// average against the mean; the image fails when any channel's p-value is below the
// Šidák-corrected level, so that a correct sampler fails with probability at most alpha
// however many channels a mistake touches.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace rt::stat {

// Per value: the mean of several lists, and the variance of one list's value about it.
struct MeanVar {
    std::vector<double> mean, var;
};

// From M >= 2 lists of equal length; var is the unbiased sample variance (divided by M - 1).
inline MeanVar mean_var(const std::vector<std::vector<double>>& samples) {
    const std::size_t m = samples.size(), n = samples.front().size();
    MeanVar r{std::vector<double>(n, 0), std::vector<double>(n, 0)};
    for (const auto& s : samples)
        for (std::size_t i = 0; i < n; ++i) r.mean[i] += s[i] / double(m);
    for (const auto& s : samples)
        for (std::size_t i = 0; i < n; ++i) r.var[i] += (s[i] - r.mean[i]) * (s[i] - r.mean[i]);
    for (std::size_t i = 0; i < n; ++i) r.var[i] /= double(m - 1);
    return r;
}

// The per-test level that makes `tests` independent tests fail together with probability alpha.
inline double sidak(double alpha, std::size_t tests) {
    return -std::expm1(std::log1p(-alpha) / double(tests));
}

// The regularised incomplete beta function I_x(a, b), with y = 1 - x passed separately so that
// an x close to 1 keeps its digits. Its continued fraction (evaluated by Lentz's method)
// converges fast only below the distribution's mean, (a + 1) / (a + b + 2); above it the
// symmetry I_x(a, b) = 1 - I_y(b, a) is used.
inline double incomplete_beta(double a, double b, double x, double y) {
    if (x <= 0) return 0;
    if (y <= 0) return 1;
    if (x > (a + 1) / (a + b + 2)) return 1 - incomplete_beta(b, a, y, x);
    const double log_front = std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log(y);
    const double tiny = 1e-300;
    const auto guard = [&](double v) { return std::abs(v) < tiny ? tiny : v; };
    // The fraction 1 / (1 + d1 / (1 + d2 / (1 + ...))), whose odd and even terms differ.
    double c = 1, d = 1 / guard(1 - (a + b) * x / (a + 1)), f = d;
    for (int k = 1; k < 100000; ++k) {
        const double even = k * (b - k) * x / ((a + 2 * k - 1) * (a + 2 * k));
        d = 1 / guard(1 + even * d);
        c = guard(1 + even / c);
        f *= c * d;
        const double odd = -(a + k) * (a + b + k) * x / ((a + 2 * k) * (a + 2 * k + 1));
        d = 1 / guard(1 + odd * d);
        c = guard(1 + odd / c);
        f *= c * d;
        if (std::abs(c * d - 1) < 1e-15) break;
    }
    return std::exp(log_front) * f / a;
}

// P(|T| >= t) for Student's t with nu degrees of freedom. From 10^7 on it is the normal
// distribution's two-sided tail: they differ by a relative 2e-5 at the levels tested here,
// and the beta function's lgamma differences lose their digits beyond.
inline double t_tail(double t, double nu) {
    if (!(t > 0)) return 1;
    if (!(nu < 1e7)) return std::erfc(t / std::sqrt(2.0));
    return std::clamp(incomplete_beta(nu / 2, 0.5, nu / (nu + t * t), t * t / (nu + t * t)), 0.0, 1.0);
}

// Two-sided p-value of an average of m renders, `average`, against the reference `mean`,
// when one render varies with variance `var`, estimated from `var_renders` renders
// (0: taken as exact). `floor` is a standard deviation added to every test: rounding, float
// against double, makes even noiseless pixels differ a little.
//
// With an estimated variance the ratio is Student's t, not normal: its tails are much
// heavier this far out (book §14.6). The floor is a known part of the spread, so the degrees
// of freedom are those of the sum, by Welch and Satterthwaite: var_renders - 1 where the
// noise dominates, growing towards the normal as the floor takes over.
inline double p_value(double average, int m, double mean, double var, double floor, std::size_t var_renders) {
    if (average == mean) return 1;  // also when nothing varies at all
    const double noise = var / double(m), spread = noise + floor * floor;
    const double t = std::abs(average - mean) / std::sqrt(spread);
    if (!(t < std::numeric_limits<double>::infinity())) return 0;  // NaN, or off where nothing varies
    double nu = std::numeric_limits<double>::infinity();
    if (var_renders > 1 && noise > 0) nu = double(var_renders - 1) * (spread / noise) * (spread / noise);
    return t_tail(t, nu);
}

struct Verdict {
    std::size_t tests = 0, failed = 0;
    double level = 0;  // the Šidák-corrected per-test level
    double smallest_p = 1;
    std::vector<double> p;  // per value
    // One global test: the smallest p-value against the corrected level. How many values
    // fail says where the mistake is (the map), not whether there is one.
    bool pass() const { return !(smallest_p < level); }
};

// `renders`: the student's M renders; `reference`: the converged mean and one render's
// variance, estimated from `var_renders` renders.
inline Verdict compare(const std::vector<std::vector<double>>& renders, const MeanVar& reference, double alpha,
                       double floor, std::size_t var_renders) {
    Verdict v;
    const std::size_t m = renders.size();
    v.tests = reference.mean.size();
    v.level = sidak(alpha, v.tests);
    v.p.resize(v.tests);
    for (std::size_t i = 0; i < v.tests; ++i) {
        double average = 0;
        for (const auto& r : renders) average += r[i] / double(m);
        v.p[i] = p_value(average, int(m), reference.mean[i], reference.var[i], floor, var_renders);
        v.failed += v.p[i] < v.level;
        v.smallest_p = std::min(v.smallest_p, v.p[i]);
    }
    return v;
}

}  // namespace rt::stat
