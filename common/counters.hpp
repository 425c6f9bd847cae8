#pragma once
// Rays cast, by kind. Each render tile counts into its own copy and the copies are summed
// at the end, so counting costs no synchronisation on the hot path.
#include <cstdint>

namespace rt {

struct RayCounters {
    std::uint64_t camera = 0;

    std::uint64_t total() const { return camera; }
    RayCounters& operator+=(const RayCounters& o) {
        camera += o.camera;
        return *this;
    }
};

}  // namespace rt
