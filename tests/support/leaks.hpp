#pragma once
// Watertightness, measured: rays aimed exactly at the shared edges and vertices of a closed
// mesh, counting those that pass between its triangles without hitting any of them.
#include "geometry/mesh.hpp"

#include <cstdint>

namespace rt {

struct LeakReport {
    long rays = 0;
    long edge_rays = 0;    // aimed at a point of an edge shared by two triangles
    long vertex_rays = 0;  // aimed exactly at a vertex
    long leaks = 0;        // hit none of the triangles around their target
};

// `rays` rays from random points on a sphere around the mesh (three times its size), three
// of four at random points of shared edges, one of four at vertices, each from an origin that
// does not see its target on the silhouette. Deterministic for a seed.
LeakReport measure_leaks(const MeshData& mesh, TriangleTest test, long rays, std::uint64_t seed);

}  // namespace rt
