#pragma once
#include "common/real.hpp"

namespace rt {

class Surface;
struct Material;

// What a successful `hit` reports. Filled only by the hit that is kept: a surface writes
// it after it knows its t is the closest one so far.
struct HitRecord {
    Real t = kInfinity;
    Vec3 p{0};       // hit point e + t d
    Vec3 normal{0};  // unit geometric normal, pointing out of the surface (never flipped)
    const Surface* surface = nullptr;
    const Material* material = nullptr;
    long primitive = -1;  // which triangle of a mesh, for picking
    // Barycentric coordinates, for the surfaces that have them (triangles).
    bool has_barycentrics = false;
    Real beta = 0;
    Real gamma = 0;
};

}  // namespace rt
