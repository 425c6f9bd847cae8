#pragma once
// Wavefront OBJ meshes, read by tinyobjloader. Only positions and faces are used (faces with
// more than three corners are fanned into triangles).
#include "geometry/mesh.hpp"

#include <string>

namespace rt {

// Throws std::runtime_error with one line naming the file and the problem.
MeshData load_obj(const std::string& path);

}  // namespace rt
