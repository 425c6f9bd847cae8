// {"type": "mesh", "file": "bunny.obj", "scale": s, "translate": [x, y, z]}: an OBJ file,
// relative to the scene file, scaled and then moved.
#include "io/obj.hpp"
#include "io/scene_types.hpp"

namespace rt {

namespace {

Shape read_mesh_file(const Fields& f) {
    const std::string path = f.file("file");  // refused here if the scene may not name it
    MeshData data;
    try {
        data = load_obj(path);
    } catch (const std::runtime_error& e) {
        f.fail("file", e.what());
    }
    const Real scale = f.length("scale", 1);
    const Vec3 translate = f.vec3("translate", Vec3(0));
    for (Vec3& p : data.positions) p = p * scale + translate;
    return Mesh(std::move(data));
}

}  // namespace

RTLAB_SURFACE_TYPE(mesh, read_mesh_file);

}  // namespace rt
