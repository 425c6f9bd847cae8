#pragma once
// The statistical image test of the noisy chapters (book §14.6), after Mitsuba 3's render
// tests: is the image a sampler makes, on average, the reference's? The reference holds, per
// pixel-channel, a converged mean and the variance of one render at the test's settings
// (measured over many renders of the reference solution). The test averages M renders of the
// student's code (M seeds) and gives each pixel-channel a z-test of that average against the
// mean; each test's level is Šidák-corrected for the number of tests, so that a correct
// sampler fails some test with probability alpha; the image passes while at most
// `max_share` of its pixel-channels fail.
#include <algorithm>
#include <cmath>
#include <cstddef>
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

// Two-sided p-value of the z-test of an average of m renders, `average`, against the
// reference `mean`, when one render varies with variance `var`. `floor` is a standard
// deviation added to every test: rounding, float against double, makes even noiseless
// pixels differ a little.
inline double z_p(double average, int m, double mean, double var, double floor) {
    const double z = std::abs(average - mean) / std::sqrt(var / double(m) + floor * floor);
    if (!(z > 0)) return 1;
    return std::erfc(z / std::sqrt(2.0));
}

struct Verdict {
    std::size_t tests = 0, failed = 0, allowed = 0;
    double level = 0;  // the Šidák-corrected per-test level
    double smallest_p = 1;
    std::vector<double> p;  // per value
    bool pass() const { return failed <= allowed; }
};

// `renders`: the student's M renders; `reference`: the converged mean and one render's variance.
inline Verdict compare(const std::vector<std::vector<double>>& renders, const MeanVar& reference, double alpha,
                       double max_share, double floor) {
    Verdict v;
    const std::size_t m = renders.size();
    v.tests = reference.mean.size();
    v.level = sidak(alpha, v.tests);
    v.allowed = std::size_t(std::floor(max_share * double(v.tests)));
    v.p.resize(v.tests);
    for (std::size_t i = 0; i < v.tests; ++i) {
        double average = 0;
        for (const auto& r : renders) average += r[i] / double(m);
        v.p[i] = z_p(average, int(m), reference.mean[i], reference.var[i], floor);
        v.failed += v.p[i] < v.level;
        v.smallest_p = std::min(v.smallest_p, v.p[i]);
    }
    return v;
}

}  // namespace rt::stat
