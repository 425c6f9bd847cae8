#pragma once
// Wavefront OBJ meshes, read by tinyobjloader. Only positions and faces are used; a face
// with more than three corners is fanned into triangles from its first corner (right for the
// convex faces OBJ exporters write, and linear in the face's size).
#include "geometry/mesh.hpp"

#include <string>

namespace rt {

// Throws std::runtime_error with one line naming the file and the problem, with its line
// number where it has one ("mesh FILE:LINE: ..."). Refuses files, faces, vertex and triangle
// counts past limits::obj_file_bytes, obj_face_corners, mesh_vertices and mesh_triangles.
MeshData load_obj(const std::string& path);
// The same for an OBJ file's text; `name` is what messages call it.
MeshData load_obj_text(const std::string& text, const std::string& name);

}  // namespace rt
