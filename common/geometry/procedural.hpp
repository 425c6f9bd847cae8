#pragma once
// Meshes the lab makes itself, so that its own scenes ship no third-party model files.
#include "geometry/mesh.hpp"

#include <cstdint>

namespace rt {

// A sphere made of 20 * 4^subdivisions triangles, vertices on the sphere, shared by index.
MeshData icosphere(const Vec3& center, Real radius, int subdivisions);

// The surface of an axis-aligned cube of side `size`, each face cut into n x n squares of two
// triangles: a closed mesh with many shared edges and vertices.
MeshData subdivided_cube(const Vec3& center, Real size, int n);

// A height field over [-size/2, size/2]^2 in x and z, n x n cells, y = a few smooth waves of
// amplitude `height`. Open (a sheet), with shared vertices.
MeshData terrain(const Vec3& center, Real size, Real height, int n);

// `count` independent random triangles (no shared vertices) inside a cube of side `size`,
// each with edges of about `scale`. Deterministic for a seed.
MeshData triangle_soup(const Vec3& center, Real size, Real scale, int count, std::uint64_t seed);

}  // namespace rt
