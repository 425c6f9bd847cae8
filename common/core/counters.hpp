#pragma once
// Rays cast, by kind, and shading work done. Each render tile counts into its own copy and
// the copies are summed at the end, so counting costs no synchronisation on the hot path.
#include "core/names.hpp"
#include "core/sampler.hpp"
#include "core/traversal_count.hpp"

#include <array>
#include <cstddef>
#include <cstdint>

namespace rt {

// Why a ray was cast: what --stats counts them by, and what the recursion context carries.
enum class RayKind : std::uint8_t { camera, shadow, reflection, refraction };
inline constexpr auto kRayKindNames = names_of<RayKind>({"camera", "shadow", "reflection", "refraction"});
inline constexpr std::size_t kRayKinds = kRayKindNames.size();

struct RayCounters {
    std::array<std::uint64_t, kRayKinds> rays{};
    // Shading work, so --stats can show what a scene skips.
    std::uint64_t light_terms = 0;     // light evaluations at shading points
    std::uint64_t specular_terms = 0;  // of those, highlights computed (not skipped)
    // Samples whose radiance came out NaN or infinite, and were left out of their pixel.
    // Zero for every scene the lab ships: the tests check it.
    std::uint64_t nonfinite_samples = 0;
    // Search work (core/traversal_count.hpp): boxes and primitives tested.
    std::uint64_t nodes_visited = 0;
    std::uint64_t primitives_tested = 0;
    // Random numbers drawn, by dimension: a scene that does not use an effect (no lens, nothing
    // moving, point lights) draws none in its dimension.
    std::array<std::uint64_t, kDimensions> draws{};

    void count(RayKind kind) { ++rays[std::size_t(kind)]; }
    std::uint64_t of(RayKind kind) const { return rays[std::size_t(kind)]; }
    std::uint64_t total() const {
        std::uint64_t sum = 0;
        for (std::uint64_t n : rays) sum += n;
        return sum;
    }
    RayCounters& operator+=(const RayCounters& o) {
        for (std::size_t k = 0; k < kRayKinds; ++k) rays[k] += o.rays[k];
        light_terms += o.light_terms;
        specular_terms += o.specular_terms;
        nonfinite_samples += o.nonfinite_samples;
        nodes_visited += o.nodes_visited;
        primitives_tested += o.primitives_tested;
        for (std::size_t d = 0; d < kDimensions; ++d) draws[d] += o.draws[d];
        return *this;
    }
};

}  // namespace rt
