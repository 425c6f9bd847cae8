// libFuzzer target: the OBJ reader (tinyobjloader behind io/obj). Every input must give a
// mesh whose triangles index its vertices, or one line of error.
#include "io/obj.hpp"
#include "fuzz_support.hpp"

#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const rt::MeshData mesh = rt::load_obj_text(rt::fuzz::text(data, size), "fuzz.obj");
        for (const auto& t : mesh.triangles)
            for (auto v : t) rt::fuzz::check(v < mesh.positions.size(), "triangle indexes past the vertices");
    } catch (const std::runtime_error& e) {
        rt::fuzz::one_line(e.what());
    }
    return 0;
}
