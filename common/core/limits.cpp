#include "core/limits.hpp"

#include <cmath>
#include <cstdio>

namespace rt::limits {

namespace {

// As people write them: 16777216, 1000000, 179.9, 1e8, 1e-6 (not 1.67772e+07 or 1e-06).
std::string number(double v) {
    char buf[40];
    const bool power_of_ten = v != 0 && std::abs(std::log10(std::abs(v)) - std::round(std::log10(std::abs(v)))) < 1e-12;
    if (std::abs(v) < 1e15 && v == std::floor(v) && !(power_of_ten && std::abs(v) >= 1e7))
        std::snprintf(buf, sizeof buf, "%.0f", v);
    else
        std::snprintf(buf, sizeof buf, "%.6g", v);
    std::string s = buf;
    const auto e = s.find('e');  // e+08 -> e8, e-06 -> e-6
    if (e != std::string::npos) {
        std::string exponent = s.substr(e + 1);
        const bool negative = exponent[0] == '-';
        exponent.erase(0, exponent.find_first_not_of("+-0"));
        s = s.substr(0, e + 1) + (negative ? "-" : "") + (exponent.empty() ? "0" : exponent);
    }
    return s;
}

}  // namespace

std::string describe(const Range& r) {
    std::string s = r.min == r.max ? "must be " + number(r.min) : "must be in " + number(r.min) + ".." + number(r.max);
    if (*r.what) s += std::string(" ") + r.what;
    return s;
}

std::string refuse(const Range& r, double value) {
    return std::string(r.name) + " " + describe(r) + ", not " + number(value);
}

}  // namespace rt::limits
