#include "render/antialiasing.hpp"

#include <cmath>

namespace rt {

namespace {
constexpr const char* kPatterns[] = {"random", "regular", "jittered"};
constexpr const char* kFilters[] = {"box", "tent"};
}  // namespace

const char* pattern_name(PixelPattern p) {
    return kPatterns[int(p)];
}
const char* filter_name(PixelFilter f) {
    return kFilters[int(f)];
}

std::optional<PixelPattern> pixel_pattern(const std::string& name) {
    for (int k = 0; k < 3; ++k)
        if (name == kPatterns[k]) return PixelPattern(k);
    return std::nullopt;
}

std::optional<PixelFilter> pixel_filter(const std::string& name) {
    for (int k = 0; k < 2; ++k)
        if (name == kFilters[k]) return PixelFilter(k);
    return std::nullopt;
}

std::optional<int> pattern_side(int spp) {
    const int n = int(std::lround(std::sqrt(double(spp))));
    if (n < 1 || n * n != spp) return std::nullopt;
    return n;
}

}  // namespace rt
