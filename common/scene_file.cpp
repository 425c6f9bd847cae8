#include "common/scene_file.hpp"

#include "common/integrators.hpp"
#include "common/json_locations.hpp"
#include "common/mesh.hpp"
#include "common/obj.hpp"
#include "common/polygon.hpp"
#include "common/procedural.hpp"
#include "common/sphere.hpp"
#include "common/surface_list.hpp"
#include "common/triangle.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace rt {

namespace {

using nlohmann::json;

// Reads values out of the parsed document, and turns any problem into a SceneError that
// points at the offending key.
class Reader {
public:
    Reader(const std::string& text, std::string filename)
        : locations_(json_locations(text)), filename_(std::move(filename)) {}

    [[noreturn]] void fail(const std::string& pointer, const std::string& message) const {
        TextPosition p;
        std::string at = pointer;
        // The nearest enclosing value that has a position (a missing key has none).
        while (true) {
            auto it = locations_.find(at);
            if (it != locations_.end()) {
                p = it->second;
                break;
            }
            if (at.empty()) break;
            at = at.substr(0, at.rfind('/'));
        }
        throw SceneError(filename_ + ":" + std::to_string(p.line) + ":" + std::to_string(p.column) + ": " +
                         (pointer.empty() ? std::string("/") : pointer) + ": " + message);
    }

    void only_keys(const json& j, const std::string& ptr, std::initializer_list<const char*> allowed) const {
        if (!j.is_object()) fail(ptr, "must be an object");
        for (const auto& [key, value] : j.items()) {
            bool ok = false;
            for (const char* a : allowed) ok |= key == a;
            if (!ok) {
                std::string list;
                for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
                fail(ptr + "/" + key, "unknown key '" + key + "' (expected one of: " + list + ")");
            }
        }
    }

    const json& need(const json& j, const std::string& ptr, const char* key) const {
        if (!j.contains(key)) fail(ptr, std::string("missing key '") + key + "'");
        return j.at(key);
    }

    Real number(const json& j, const std::string& ptr) const {
        if (!j.is_number()) fail(ptr, "must be a number");
        const double v = j.get<double>();
        if (!std::isfinite(v)) fail(ptr, "must be finite");
        return Real(v);
    }
    Real positive(const json& j, const std::string& ptr) const {
        const Real v = number(j, ptr);
        if (!(v > 0)) fail(ptr, "must be > 0");
        return v;
    }
    int integer(const json& j, const std::string& ptr, int lo, int hi) const {
        if (!j.is_number_integer()) fail(ptr, "must be a whole number");
        const auto v = j.get<long long>();
        if (v < lo || v > hi) fail(ptr, "must be in " + std::to_string(lo) + ".." + std::to_string(hi));
        return int(v);
    }
    std::string text(const json& j, const std::string& ptr) const {
        if (!j.is_string()) fail(ptr, "must be a string");
        return j.get<std::string>();
    }
    Vec3 vec3(const json& j, const std::string& ptr) const {
        if (!j.is_array() || j.size() != 3) fail(ptr, "must be an array of 3 numbers");
        return Vec3(number(j[0], ptr + "/0"), number(j[1], ptr + "/1"), number(j[2], ptr + "/2"));
    }
    Color color(const json& j, const std::string& ptr) const {
        const Vec3 c = vec3(j, ptr);
        if (c.x < 0 || c.y < 0 || c.z < 0) fail(ptr, "colour components must be >= 0");
        return Color(c);
    }

private:
    std::map<std::string, TextPosition> locations_;
    std::string filename_;
};

Camera read_camera(const Reader& r, const json& j, const std::string& ptr) {
    r.only_keys(j, ptr, {"projection", "eye", "target", "up", "fov", "window_height", "focal_distance"});
    Camera cam;
    if (j.contains("projection")) {
        const std::string p = r.text(j["projection"], ptr + "/projection");
        if (p == "perspective") cam.projection = Projection::perspective;
        else if (p == "orthographic") cam.projection = Projection::orthographic;
        else r.fail(ptr + "/projection", "must be \"perspective\" or \"orthographic\", not \"" + p + "\"");
    }
    cam.eye = r.vec3(r.need(j, ptr, "eye"), ptr + "/eye");
    cam.target = r.vec3(r.need(j, ptr, "target"), ptr + "/target");
    if (j.contains("up")) cam.up = r.vec3(j["up"], ptr + "/up");
    if (j.contains("fov")) {
        cam.vertical_fov_degrees = r.positive(j["fov"], ptr + "/fov");
        if (cam.vertical_fov_degrees >= 180) r.fail(ptr + "/fov", "must be less than 180 degrees");
    }
    if (j.contains("window_height")) cam.window_height = r.positive(j["window_height"], ptr + "/window_height");
    if (j.contains("focal_distance")) cam.focal_distance = r.positive(j["focal_distance"], ptr + "/focal_distance");
    try {
        (void)cam.view(2, 2);  // eye == target, up along the view, ...
    } catch (const std::invalid_argument& e) {
        r.fail(ptr, e.what());
    }
    return cam;
}

Material read_material(const Reader& r, const json& j, const std::string& ptr, const std::string& name) {
    r.only_keys(j, ptr, {"diffuse", "specular", "exponent"});
    Material m;
    m.name = name;
    if (j.contains("diffuse")) m.diffuse = r.color(j["diffuse"], ptr + "/diffuse");
    if (j.contains("specular")) m.specular = r.color(j["specular"], ptr + "/specular");
    if (j.contains("exponent")) m.exponent = float(r.positive(j["exponent"], ptr + "/exponent"));
    return m;
}

Light read_light(const Reader& r, const json& j, const std::string& ptr) {
    if (!j.is_object()) r.fail(ptr, "must be an object");
    const std::string type = r.text(r.need(j, ptr, "type"), ptr + "/type");
    Light l;
    if (type == "point") {
        r.only_keys(j, ptr, {"type", "position", "color"});
        l.type = Light::Type::point;
        l.position = r.vec3(r.need(j, ptr, "position"), ptr + "/position");
    } else if (type == "directional") {
        r.only_keys(j, ptr, {"type", "direction", "color"});
        l.type = Light::Type::directional;
        l.direction = r.vec3(r.need(j, ptr, "direction"), ptr + "/direction");
        if (glm::dot(l.direction, l.direction) == 0) r.fail(ptr + "/direction", "must not be zero");
    } else {
        r.fail(ptr + "/type", "must be \"point\" or \"directional\", not \"" + type + "\"");
    }
    if (j.contains("color")) l.color = r.color(j["color"], ptr + "/color");
    return l;
}

std::vector<Vec3> read_points(const Reader& r, const json& j, const std::string& ptr, std::size_t min, std::size_t max) {
    if (!j.is_array() || j.size() < min || j.size() > max)
        r.fail(ptr, min == max ? "must be an array of " + std::to_string(min) + " points"
                               : "must be an array of at least " + std::to_string(min) + " points");
    std::vector<Vec3> points;
    for (std::size_t i = 0; i < j.size(); ++i) points.push_back(r.vec3(j[i], ptr + "/" + std::to_string(i)));
    return points;
}

// Keys every surface may have, besides its own.
#define RT_SURFACE_KEYS "type", "name", "material"

std::shared_ptr<Surface> read_surface(const Reader& r, const json& j, const std::string& ptr,
                                      const std::string& base_dir, SceneSummary& summary) {
    if (!j.is_object()) r.fail(ptr, "must be an object");
    const std::string type = r.text(r.need(j, ptr, "type"), ptr + "/type");
    const std::string name = j.contains("name") ? r.text(j["name"], ptr + "/name") : type + " " + ptr.substr(ptr.rfind('/') + 1);
    auto mesh = [&](MeshData data) {
        auto m = std::make_shared<TriangleMesh>(name, std::move(data));
        summary.triangles += long(m->data().triangles.size());
        summary.degenerate_triangles += long(m->dropped_degenerate());
        return m;
    };
    try {
        if (type == "sphere") {
            r.only_keys(j, ptr, {RT_SURFACE_KEYS, "center", "radius"});
            return std::make_shared<Sphere>(name, r.vec3(r.need(j, ptr, "center"), ptr + "/center"),
                                            r.positive(r.need(j, ptr, "radius"), ptr + "/radius"));
        }
        if (type == "triangle") {
            r.only_keys(j, ptr, {RT_SURFACE_KEYS, "vertices"});
            const auto v = read_points(r, r.need(j, ptr, "vertices"), ptr + "/vertices", 3, 3);
            summary.triangles += 1;
            return std::make_shared<Triangle>(name, v[0], v[1], v[2]);
        }
        if (type == "polygon") {
            r.only_keys(j, ptr, {RT_SURFACE_KEYS, "vertices"});
            return std::make_shared<Polygon>(name, read_points(r, r.need(j, ptr, "vertices"), ptr + "/vertices", 3, 100000));
        }
        if (type == "mesh") {
            r.only_keys(j, ptr, {RT_SURFACE_KEYS, "file", "scale", "translate"});
            std::filesystem::path file = r.text(r.need(j, ptr, "file"), ptr + "/file");
            if (file.is_relative()) file = std::filesystem::path(base_dir) / file;
            MeshData data;
            try {
                data = load_obj(file.string());
            } catch (const std::runtime_error& e) {
                r.fail(ptr + "/file", e.what());
            }
            const Real scale = j.contains("scale") ? r.positive(j["scale"], ptr + "/scale") : Real(1);
            const Vec3 translate = j.contains("translate") ? r.vec3(j["translate"], ptr + "/translate") : Vec3(0);
            for (Vec3& p : data.positions) p = p * scale + translate;
            return mesh(std::move(data));
        }
        if (type == "icosphere") {
            r.only_keys(j, ptr, {RT_SURFACE_KEYS, "center", "radius", "subdivisions"});
            return mesh(icosphere(r.vec3(r.need(j, ptr, "center"), ptr + "/center"),
                                  r.positive(r.need(j, ptr, "radius"), ptr + "/radius"),
                                  j.contains("subdivisions") ? r.integer(j["subdivisions"], ptr + "/subdivisions", 0, 7) : 2));
        }
        if (type == "cube") {
            r.only_keys(j, ptr, {RT_SURFACE_KEYS, "center", "size", "subdivisions"});
            return mesh(subdivided_cube(r.vec3(r.need(j, ptr, "center"), ptr + "/center"),
                                        r.positive(r.need(j, ptr, "size"), ptr + "/size"),
                                        j.contains("subdivisions") ? r.integer(j["subdivisions"], ptr + "/subdivisions", 1, 256) : 1));
        }
        if (type == "terrain") {
            r.only_keys(j, ptr, {RT_SURFACE_KEYS, "center", "size", "height", "cells"});
            return mesh(terrain(r.vec3(r.need(j, ptr, "center"), ptr + "/center"),
                                r.positive(r.need(j, ptr, "size"), ptr + "/size"),
                                r.number(r.need(j, ptr, "height"), ptr + "/height"),
                                j.contains("cells") ? r.integer(j["cells"], ptr + "/cells", 1, 2048) : 64));
        }
        if (type == "soup") {
            r.only_keys(j, ptr, {RT_SURFACE_KEYS, "center", "size", "scale", "count", "seed"});
            return mesh(triangle_soup(r.vec3(r.need(j, ptr, "center"), ptr + "/center"),
                                      r.positive(r.need(j, ptr, "size"), ptr + "/size"),
                                      r.positive(r.need(j, ptr, "scale"), ptr + "/scale"),
                                      r.integer(r.need(j, ptr, "count"), ptr + "/count", 1, 1000000),
                                      j.contains("seed") ? std::uint64_t(r.integer(j["seed"], ptr + "/seed", 0, 2147483647)) : 1));
        }
    } catch (const std::invalid_argument& e) {  // a degenerate polygon, triangle or mesh
        r.fail(ptr, e.what());
    }
    r.fail(ptr + "/type", "unknown surface type \"" + type +
                              "\" (expected sphere, triangle, polygon, mesh, icosphere, cube, terrain or soup)");
}

}  // namespace

Scene load_scene_text(const std::string& text, const std::string& filename, const std::string& base_dir,
                      SceneSummary* summary_out) {
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::parse_error& e) {
        const TextPosition p = position_of(text, e.byte > 0 ? e.byte - 1 : 0);
        std::string what = e.what();
        const auto colon = what.rfind(": ");  // drop nlohmann's "[json.exception...] parse error at ..." prefix
        if (colon != std::string::npos) what = what.substr(colon + 2);
        throw SceneError(filename + ":" + std::to_string(p.line) + ":" + std::to_string(p.column) +
                         ": not valid JSON: " + what);
    }
    const Reader r(text, filename);
    r.only_keys(doc, "", {"$schema", "description", "camera", "shading", "background", "ambient", "materials", "lights",
                          "surfaces"});
    SceneSummary summary;
    summary.from_file = true;
    Scene scene;
    scene.description = doc.contains("description") ? r.text(doc["description"], "/description") : "";
    scene.camera = read_camera(r, r.need(doc, "", "camera"), "/camera");
    const std::string shading = doc.contains("shading") ? r.text(doc["shading"], "/shading") : "phong";
    scene.integrator = make_integrator(shading);
    if (!scene.integrator)
        r.fail("/shading", "unknown shading \"" + shading + "\" (expected phong, normal, barycentric or direction)");
    if (doc.contains("background")) scene.background = r.color(doc["background"], "/background");
    if (doc.contains("ambient")) scene.ambient = r.color(doc["ambient"], "/ambient");

    std::map<std::string, std::shared_ptr<const Material>> materials;
    if (doc.contains("materials")) {
        const json& ms = doc["materials"];
        if (!ms.is_object()) r.fail("/materials", "must be an object of named materials");
        for (const auto& [name, m] : ms.items())
            materials[name] = std::make_shared<Material>(read_material(r, m, "/materials/" + name, name));
    }
    if (doc.contains("lights")) {
        const json& ls = doc["lights"];
        if (!ls.is_array()) r.fail("/lights", "must be an array");
        for (std::size_t i = 0; i < ls.size(); ++i) scene.lights.push_back(read_light(r, ls[i], "/lights/" + std::to_string(i)));
    }
    summary.lights_black = scene.drop_unused_lights();
    summary.lights = int(scene.lights.size());

    const json& ss = r.need(doc, "", "surfaces");
    if (!ss.is_array()) r.fail("/surfaces", "must be an array");
    auto world = std::make_shared<SurfaceList>();
    std::set<std::string> used;
    for (std::size_t i = 0; i < ss.size(); ++i) {
        const std::string ptr = "/surfaces/" + std::to_string(i);
        auto s = read_surface(r, ss[i], ptr, base_dir, summary);
        if (ss[i].contains("material")) {
            const std::string m = r.text(ss[i]["material"], ptr + "/material");
            auto it = materials.find(m);
            if (it == materials.end()) r.fail(ptr + "/material", "no material named \"" + m + "\" in /materials");
            s->set_material(it->second);
            used.insert(m);
        }
        world->add(std::move(s));
    }
    summary.surfaces = int(ss.size());
    summary.materials = int(used.size());
    summary.materials_unused = int(materials.size() - used.size());
    if (!world->surfaces().empty()) scene.world = std::move(world);
    if (summary_out) *summary_out = summary;
    return scene;  // unused materials go out of scope here: nothing refers to them
}

Scene load_scene_file(const std::string& path, SceneSummary* summary) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError(path + ": cannot open scene file");
    std::ostringstream text;
    text << in.rdbuf();
    const std::string dir = std::filesystem::path(path).parent_path().string();
    return load_scene_text(text.str(), path, dir.empty() ? "." : dir, summary);
}

}  // namespace rt
