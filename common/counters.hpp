#pragma once
// Rays cast, by kind, and shading work done. Each render tile counts into its own copy and the copies are summed
// at the end, so counting costs no synchronisation on the hot path.
#include <cstdint>

namespace rt {

struct RayCounters {
    std::uint64_t camera = 0;
    // Shading work, so --stats can show what a scene skips.
    std::uint64_t light_terms = 0;     // light evaluations at shading points
    std::uint64_t specular_terms = 0;  // of those, highlights computed (not skipped)

    std::uint64_t total() const { return camera; }
    RayCounters& operator+=(const RayCounters& o) {
        camera += o.camera;
        light_terms += o.light_terms;
        specular_terms += o.specular_terms;
        return *this;
    }
};

}  // namespace rt
