#include "io/obj.hpp"

#include <tiny_obj_loader.h>

#include <filesystem>
#include <stdexcept>

namespace rt {

MeshData load_obj(const std::string& path) {
    if (!std::filesystem::is_regular_file(path)) throw std::runtime_error("mesh " + path + ": no such file");
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(path, config)) {
        std::string why = reader.Error();
        while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
        const auto newline = why.find('\n');
        if (newline != std::string::npos) why = why.substr(0, newline);
        throw std::runtime_error("mesh " + path + ": " + (why.empty() ? "not a valid OBJ file" : why));
    }
    const auto& positions = reader.GetAttrib().vertices;
    MeshData mesh;
    mesh.positions.reserve(positions.size() / 3);
    for (std::size_t i = 0; i + 2 < positions.size(); i += 3)
        mesh.positions.push_back(Vec3(positions[i], positions[i + 1], positions[i + 2]));
    for (const auto& shape : reader.GetShapes()) {
        const auto& idx = shape.mesh.indices;
        std::size_t offset = 0;
        for (const auto corners : shape.mesh.num_face_vertices) {
            if (corners == 3) {
                const auto v = [&](std::size_t k) {
                    const int i = idx[offset + k].vertex_index;
                    if (i < 0 || std::size_t(i) >= mesh.positions.size())
                        throw std::runtime_error("mesh " + path + ": a face uses vertex " + std::to_string(i + 1) +
                                                 " of " + std::to_string(mesh.positions.size()));
                    return std::uint32_t(i);
                };
                mesh.triangles.push_back({v(0), v(1), v(2)});
            }
            offset += corners;
        }
    }
    if (mesh.triangles.empty()) throw std::runtime_error("mesh " + path + ": no triangles in the file");
    try {
        validate(mesh, "mesh " + path);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(e.what());
    }
    return mesh;
}

}  // namespace rt
