#pragma once
// Least-squares fits on log-log data, for the benchmarks' slopes.
#include <cmath>
#include <cstddef>
#include <vector>

namespace rt::bench {

// The slope of log10(y) against log10(x) by least squares (x, y > 0); 0 for fewer than two points.
inline double loglog_slope(const std::vector<double>& x, const std::vector<double>& y) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const std::size_t m = x.size();
    for (std::size_t i = 0; i < m; ++i) {
        const double lx = std::log10(x[i]), ly = std::log10(y[i]);
        sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
    }
    const double d = double(m) * sxx - sx * sx;
    return m < 2 || d == 0 ? 0 : (double(m) * sxy - sx * sy) / d;
}

// Where the piecewise log-log line through (x[i], y[i]) (y falling as x rises) reaches y = target:
// interpolated between the two points around it, extrapolated from the last two past the end.
// NaN with fewer than two points.
inline double loglog_reach(const std::vector<double>& x, const std::vector<double>& y, double target) {
    const std::size_t m = x.size();
    if (m < 2) return std::nan("");
    std::size_t i = 0;
    while (i + 2 < m && y[i + 1] > target) ++i;
    const double t = (std::log(target) - std::log(y[i])) / (std::log(y[i + 1]) - std::log(y[i]));
    return std::exp(std::log(x[i]) + t * (std::log(x[i + 1]) - std::log(x[i])));
}

}  // namespace rt::bench
