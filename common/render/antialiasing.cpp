#include "render/antialiasing.hpp"

#include <cmath>

namespace rt {

std::optional<int> pattern_side(int spp) {
    const int n = int(std::lround(std::sqrt(double(spp))));
    if (n < 1 || n * n != spp) return std::nullopt;
    return n;
}

}  // namespace rt
