#include "io/obj.hpp"

#include "core/text.hpp"
#include "geometry/limits.hpp"
#include "io/input_file.hpp"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string_view>

namespace rt {

namespace {

[[noreturn]] void fail(const std::string& name, std::size_t line, const std::string& message) {
    throw std::runtime_error(
        one_line("mesh " + name + (line ? ":" + std::to_string(line) : std::string()) + ": " + message));
}

// The whitespace-separated words of a line, as `>>` would read them, without a stream:
// building an istringstream per line cost more than tinyobjloader's whole parse.
struct Words {
    std::string_view rest;
    bool next(std::string_view& word) {
        const auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
        std::size_t k = 0;
        while (k < rest.size() && space(rest[k])) ++k;
        if (k == rest.size()) return false;
        std::size_t e = k;
        while (e < rest.size() && !space(rest[e])) ++e;
        word = rest.substr(k, e - k);
        rest.remove_prefix(e);
        return true;
    }
};

// A coordinate that is a number, finite in double, and nothing else. tinyobjloader reads
// anything else as 0 ("nan", "abc", "0x1p3") and 1e400 as infinity, without a word.
// from_chars takes the number's whole text or says where it stopped; it refuses 1e400 as
// out of range and reads "nan" and "inf", which isfinite then refuses.
bool finite_number(std::string_view token) {
    const bool plus = token[0] == '+' && token.size() > 1 && token[1] != '-';  // from_chars takes '-', not '+'
    const char* end = token.data() + token.size();
    double value = 0;
    const auto [stop, error] = std::from_chars(token.data() + (plus ? 1 : 0), end, value);
    return error == std::errc() && stop == end && std::isfinite(value);
}

// The three coordinates of a "v" or "vn" line (what follows them, a w or a colour, is not
// read): each a finite number.
void check_coordinates(Words fields, const std::string& name, std::size_t line, const char* what) {
    std::string_view token;
    for (int k = 0; k < 3; ++k) {
        if (!fields.next(token) || token[0] == '#')
            fail(name, line, std::string(what) + " has " + std::to_string(k) + " coordinates, not 3");
        if (!finite_number(token))
            fail(name, line,
                 std::string(what) + " coordinate '" + std::string(token.substr(0, 40)) + "' is not a finite number");
    }
}

// One pass over the text before tinyobjloader sees it, for what the loader cannot report:
// it keeps face indices in an int (99999999999 wraps round), reads a coordinate that is not
// a number as 0, and gives no line numbers. Also enforces the count limits before any
// memory is spent on them.
void check_counts_and_indices(const std::string& text, const std::string& name) {
    std::size_t number = 0;
    double vertices = 0, triangles = 0;
    long long highest = 0;  // the highest positive index, and where it is
    std::size_t highest_line = 0;
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t newline = std::min(text.find('\n', at), text.size());
        const std::string_view line(text.data() + at, newline - at);
        at = newline + 1;
        ++number;
        const std::size_t i = line.find_first_not_of(" \t");
        if (i != std::string_view::npos && line.substr(i, 2) == "vn" && i + 2 < line.size() &&
            std::isspace(static_cast<unsigned char>(line[i + 2]))) {
            check_coordinates(Words{line.substr(i + 2)}, name, number, "vertex normal");
            continue;
        }
        if (i == std::string_view::npos || i + 1 >= line.size() ||
            !std::isspace(static_cast<unsigned char>(line[i + 1])))
            continue;
        if (line[i] == 'v') {
            if (++vertices > limits::mesh_vertices.max)
                fail(name, number, limits::refuse(limits::mesh_vertices, vertices));
            check_coordinates(Words{line.substr(i + 1)}, name, number, "vertex");
            continue;
        }
        if (line[i] != 'f') continue;
        Words corners{line.substr(i + 1)};
        std::string_view corner;
        int count = 0;
        while (corners.next(corner)) {
            ++count;
            // The vertex index: an optional sign and digits, before any '/'.
            std::size_t k = 0;
            const bool negative = corner[0] == '-';
            if (corner[0] == '-' || corner[0] == '+') ++k;
            long long index = 0;
            bool digits = false;
            for (; k < corner.size() && std::isdigit(static_cast<unsigned char>(corner[k])); ++k) {
                digits = true;
                index = index < 1000000000000LL ? index * 10 + (corner[k] - '0') : index;  // saturate
            }
            if (!digits)
                fail(name, number, "face corner '" + std::string(corner.substr(0, 40)) + "' has no vertex index");
            if (index == 0) fail(name, number, "vertex index 0 (OBJ counts vertices from 1)");
            if (negative && double(index) > vertices)
                fail(name, number,
                     "vertex index -" + std::to_string(index) + " reaches before the first vertex (" +
                         std::to_string(std::size_t(vertices)) + " so far)");
            if (!negative && index > highest) highest = index, highest_line = number;
        }
        // At least a triangle; and tinyobjloader counts a face's corners in a byte, so past 255
        // it would silently wrap.
        if (!limits::contains(limits::obj_face_corners, count))
            fail(name, number, limits::refuse(limits::obj_face_corners, count));
        triangles += count - 2;
        if (triangles > limits::mesh_triangles.max)
            fail(name, number, limits::refuse(limits::mesh_triangles, triangles));
    }
    if (double(highest) > vertices)
        fail(name, highest_line,
             "vertex index " + (highest >= 1000000000000LL ? std::string("past 10^12") : std::to_string(highest)) +
                 ", but the file has " + std::to_string(std::size_t(vertices)) + " vertices");
}

}  // namespace

MeshData load_obj_text(const std::string& text, const std::string& name) {
    check_counts_and_indices(text, name);
    tinyobj::ObjReaderConfig config;
    config.triangulate = false;  // fanned below: tinyobjloader's triangulation is quadratic in a face's size
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    // From a string: "mtllib" lines must not make the loader open other files.
    if (!reader.ParseFromString(text, "", config)) {
        std::string why = reader.Error();
        while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
        const auto newline = why.find('\n');
        if (newline != std::string::npos) why = why.substr(0, newline);
        fail(name, 0, why.empty() ? "not a valid OBJ file" : why);
    }
    const auto& positions = reader.GetAttrib().vertices;
    MeshData mesh;
    mesh.positions.reserve(positions.size() / 3);
    for (std::size_t i = 0; i + 2 < positions.size(); i += 3)
        mesh.positions.push_back(Vec3(positions[i], positions[i + 1], positions[i + 2]));
    // Vertex normals ("vn"), used for smooth shading when every corner of every face names
    // one; a file that gives them for some corners only is shaded flat.
    const auto& normals = reader.GetAttrib().normals;
    bool all_normals = !normals.empty();
    for (const auto& shape : reader.GetShapes())
        for (const auto& corner : shape.mesh.indices)
            if (corner.normal_index < 0 || std::size_t(corner.normal_index) * 3 + 2 >= normals.size())
                all_normals = false;
    if (all_normals)
        for (std::size_t i = 0; i + 2 < normals.size(); i += 3)
            mesh.normals.push_back(Vec3(normals[i], normals[i + 1], normals[i + 2]));
    for (const auto& shape : reader.GetShapes()) {
        const auto& idx = shape.mesh.indices;
        std::size_t offset = 0;
        for (const auto corners : shape.mesh.num_face_vertices) {
            const auto v = [&](std::size_t k) {
                const int i = idx[offset + k].vertex_index;
                if (i < 0 || std::size_t(i) >= mesh.positions.size())  // the check above makes this unreachable
                    fail(name, 0, "a face uses a vertex the file does not have");
                return std::uint32_t(i);
            };
            const auto n = [&](std::size_t k) { return std::uint32_t(idx[offset + k].normal_index); };
            for (std::size_t k = 1; k + 1 < corners; ++k) {
                mesh.triangles.push_back({v(0), v(k), v(k + 1)});
                if (all_normals) mesh.normal_triangles.push_back({n(0), n(k), n(k + 1)});
            }
            offset += corners;
        }
    }
    if (mesh.triangles.empty()) fail(name, 0, "no triangles in the file");
    try {
        validate(mesh, "mesh " + name);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(e.what());
    }
    return mesh;
}

MeshData load_obj(const std::string& path) {
    return load_obj_text(read_input_file(path, "mesh", limits::obj_file_bytes), path);
}

}  // namespace rt
