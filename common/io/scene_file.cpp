#include "io/scene_file.hpp"

#include "core/text.hpp"
#include "io/input_file.hpp"
#include "io/json_locations.hpp"
#include "io/scene_types.hpp"
#include "render/integrators.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <memory>

namespace rt {

namespace {

using nlohmann::json;

Camera read_camera(const Fields& f) {
    Camera cam;
    cam.projection = f.choice("projection", kProjectionNames, "projection", cam.projection);
    cam.eye = f.vec3("eye");
    cam.target = f.vec3("target");
    cam.up = f.vec3("up", cam.up);
    cam.vertical_fov_degrees = f.number("fov", limits::field_of_view, cam.vertical_fov_degrees);
    cam.window_height = f.length("window_height", cam.window_height);
    cam.focal_distance = f.length("focal_distance", cam.focal_distance);
    // Chapter 16: a thin lens; chapter 18: the shutter interval.
    cam.aperture = f.number("aperture", limits::aperture, cam.aperture);
    cam.focus_distance = f.length("focus_distance", cam.focus_distance);
    cam.lens = f.choice("lens", kLensNames, "lens", cam.lens);
    if ((f.has("focus_distance") || f.has("lens")) && !(cam.aperture > 0))
        f.fail(f.has("lens") ? "lens" : "focus_distance", "a lens needs an aperture > 0");
    if (f.has("shutter")) {
        const std::vector<Real> times = f.numbers("shutter", 2, limits::shutter);
        cam.shutter_open = times[0];
        cam.shutter_close = times[1];
        if (!(cam.shutter_open <= cam.shutter_close)) f.fail("shutter", "closes before it opens");
    }
    f.done();
    try {
        cam.validate();
    } catch (const std::invalid_argument& e) {
        f.fail("", e.what());
    }
    return cam;
}

Light read_light(const Fields& f) {
    const std::string type = f.text("type");
    for (const LightType* t : light_types()) {
        if (type != t->name) continue;
        Light light = t->read(f);
        light.color = f.color("color", limits::radiance, light.color);
        f.done();
        return light;
    }
    f.fail("type", "unknown light type \"" + type + "\" (expected " + type_names(light_types()) + ")");
}

// What reading a shape may need besides its own fields: a CSG object's operands name
// materials and shapes of the file.
struct Loader {
    const JsonReader& reader;
    const std::map<std::string, Material>& materials;
    std::map<std::string, MaterialId>& used;  // materials kept, by name
    Scene& scene;
    const std::map<std::string, std::shared_ptr<const Shape>>& shapes;
    std::map<std::string, int>& shape_uses;
    // Reading /shapes itself: its entries are read in no order a file can rely on, so none
    // may name another.
    bool in_shapes = false;

    // The id of the material a "material" key names, keeping it on first use.
    MaterialId material(const Fields& f) const {
        const std::string name = f.text("material");
        const auto it = materials.find(name);
        if (it == materials.end()) f.fail("material", "no material named \"" + name + "\" in /materials");
        auto [slot, added] = used.emplace(name, 0);
        if (added) slot->second = scene.add_material(it->second);
        return slot->second;
    }
};

Shape read_csg(const Loader& loader, const Fields& f);

// The shape of one /surfaces (or /shapes) entry, by its type's module. A key every type
// takes: "smooth" (meshes only) gives a mesh vertex normals for smooth shading. The caller
// reads the entry's other keys and then checks that none is left (Fields::done).
Shape read_shape(const Loader& loader, const Fields& f) {
    const std::string type = f.text("type");
    if (type == "csg") return read_csg(loader, f);
    for (const SurfaceType* t : surface_types()) {
        if (type != t->name) continue;
        try {
            Shape shape = t->read(f);
            if (f.has("smooth")) {
                const Mesh* mesh = std::get_if<Mesh>(&shape);
                if (!mesh)
                    f.fail("smooth", "only meshes have vertex normals; a " + type + " is shaded by its own normal");
                if (f.flag("smooth", false)) shape = mesh->smoothed();
            }
            return shape;
        } catch (const std::invalid_argument& e) {  // degenerate geometry, a limit passed
            f.fail("", e.what());
        }
    }
    if (type == "instance") f.fail("type", "an instance names a shape of /shapes; it cannot be one there");
    f.fail("type",
           "unknown surface type \"" + type + "\" (expected " + type_names(surface_types()) + ", csg or instance)");
}

// {"type": "instance", "shape": name}: a shape of /shapes, shared, not copied. `reused`: the
// shape was named before.
std::shared_ptr<const Shape> read_instance(const Loader& loader, const Fields& f, bool& reused) {
    if (loader.in_shapes)
        f.fail("type", "an operand of a shape in /shapes cannot name another shape; give the operand itself");
    const std::string name = f.text("shape");
    const auto it = loader.shapes.find(name);
    if (it == loader.shapes.end()) f.fail("shape", "no shape named \"" + name + "\" in /shapes");
    reused = loader.shape_uses[name]++ > 0;
    return it->second;
}

// The shape of a /surfaces entry or a CSG operand: an instance or a shape of its own.
std::shared_ptr<const Shape> read_entry_shape(const Loader& loader, const Fields& f, bool& reused) {
    if (f.text("type") == "instance") return read_instance(loader, f, reused);
    reused = false;
    return std::make_shared<const Shape>(read_shape(loader, f));
}

// A shape seen through the entry's "transform", if it has one: an instance of it, which must
// stay where coordinates may be (limits.hpp), as the shapes of the file do.
std::shared_ptr<const Shape> transformed(const Fields& f, std::shared_ptr<const Shape> base) {
    if (!f.has("transform")) return base;
    const Affine to_world = read_transform(f, "transform");
    if (to_world.is_identity()) return base;
    auto shape = std::make_shared<const Shape>(Instance(base, to_world));  // read_transform refused a singular one
    const Box box = bounding_box(*shape);
    for (const Vec3& corner : {box.min, box.max})
        for (int k = 0; k < 3; ++k)
            if (!limits::contains(limits::coordinate, double(corner[k])))
                f.fail("transform", "moves the shape past the coordinate limits (" +
                                        limits::refuse(limits::coordinate, double(corner[k])) + ")");
    return shape;
}

// One operand of a CSG object: any solid surface entry (an instance of /shapes too), with
// its own material and name if it gives them.
CsgOperand read_operand(const Loader& loader, const Fields& f) {
    bool reused = false;
    const std::shared_ptr<const Shape> base = read_entry_shape(loader, f, reused);
    const std::string why = not_solid(*base);
    if (!why.empty()) {
        const std::string name = f.text("name", "");
        f.fail("", "a CSG operand must be a closed solid: " + (name.empty() ? "" : "'" + name + "': ") + why);
    }
    CsgOperand operand{transformed(f, base), kNone, f.text("name", "")};
    if (f.has("material")) operand.material = loader.material(f);
    f.done();
    return operand;
}

// Operands [first, last) joined by `op` as a balanced tree: a long list nests log2(n) deep,
// not n deep, and the spans are computed recursively.
CsgOperand join(CsgOp op, std::vector<CsgOperand>& operands, std::size_t first, std::size_t last, Real thin) {
    if (last - first == 1) return std::move(operands[first]);
    const std::size_t mid = first + (last - first) / 2;
    CsgOperand left = join(op, operands, first, mid, thin);
    CsgOperand right = join(op, operands, mid, last, thin);
    return CsgOperand{std::make_shared<const Shape>(Csg(op, std::move(left), std::move(right), thin))};
}

// {"type": "csg", "op": "union" | "intersection" | "difference", "operands": [A, B, C, ...],
// "thin": length}: A op B op C ...; a difference takes every later operand from the first,
// A - (B u C u ...).
Shape read_csg(const Loader& loader, const Fields& f) {
    const CsgOp op = f.choice("op", kCsgOpNames, "CSG operation");
    const std::vector<Fields> list = f.objects("operands");
    if (!limits::contains(limits::csg_operands, double(list.size())))
        f.fail("operands", limits::refuse(limits::csg_operands, double(list.size())));
    const Real thin = f.has("thin") ? f.number("thin", limits::csg_thin) : Real(-1);
    std::vector<CsgOperand> operands;
    for (const Fields& o : list) operands.push_back(read_operand(loader, o));
    try {
        if (op != CsgOp::difference) return *join(op, operands, 0, operands.size(), thin).shape;
        CsgOperand cut = join(CsgOp::union_of, operands, 1, operands.size(), thin);
        return Csg(op, std::move(operands[0]), std::move(cut), thin);
    } catch (const std::invalid_argument& e) {  // an empty intersection
        f.fail("", e.what());
    }
}

void count_triangles(const Shape& shape, SceneSummary& summary) {
    match(
        shape,
        [&](const Mesh& mesh) {
            summary.triangles += mesh.data().triangles.size();
            summary.degenerate_triangles += mesh.dropped_degenerate();
        },
        [&](const Triangle&) { summary.triangles += 1; },
        [&](const Csg& csg) {  // its operands' own, not instances of /shapes
            count_triangles(*csg.left().shape, summary);
            count_triangles(*csg.right().shape, summary);
        },
        // An instance's shape is counted once, where /shapes defines it.
        [](const Instance&) {}, [](const Sphere&) {}, [](const Polygon&) {}, [](const Cuboid&) {});
}

std::string where(const std::string& text, const std::string& filename, std::size_t offset) {
    const TextPosition p = position_of(text, offset);
    return filename + ":" + std::to_string(p.line) + ":" + std::to_string(p.column) + ": ";
}

json parse(const std::string& text, const std::string& filename) {
    // Before the parser: what it would accept but we could not hold (1e400 overflows a double)
    // or should not (nesting without end costs memory and time, and means nothing here).
    if (const auto problem = check_json_text(text))
        throw SceneError(one_line(where(text, filename, problem->offset) +
                                  (problem->pointer.empty() ? "/" : problem->pointer) + ": " + problem->message));
    try {
        return json::parse(text);
    } catch (const json::parse_error& e) {
        std::string what = e.what();
        const auto colon = what.rfind(": ");  // drop nlohmann's "[json.exception...] parse error at ..." prefix
        if (colon != std::string::npos) what = what.substr(colon + 2);
        throw SceneError(one_line(where(text, filename, e.byte > 0 ? e.byte - 1 : 0) + "not valid JSON: " + what));
    } catch (const json::exception& e) {  // anything the check above missed: still one line, exit 2
        throw SceneError(one_line(filename + ": not valid JSON: " + e.what()));
    }
}

}  // namespace

Camera load_camera_text(const std::string& text, const std::string& filename) {
    const json doc = parse(text, filename);
    const JsonReader reader(text, filename, ".");
    return read_camera(Fields(reader, doc, ""));
}

Scene load_scene_text(const std::string& text, const std::string& filename, const std::string& base_dir,
                      SceneSummary* summary_out, const FileAccess& access) {
    const json doc = parse(text, filename);
    const JsonReader reader(text, filename, base_dir, access);
    const Fields top(reader, doc, "");
    SceneSummary summary;
    summary.from_file = true;
    Scene scene;
    (void)top.text("$schema", "");  // where an editor finds the schema; nothing to the loader
    scene.description = top.text("description", "");
    if (!top.has("camera")) top.fail("", "missing key 'camera'");
    scene.camera = read_camera(top.object("camera"));
    scene.integrator = make_integrator(top.choice("shading", kShadingNames, "shading", Shading::phong));
    scene.max_depth = top.integer("max_depth", limits::recursion_depth, scene.max_depth);
    scene.accel_kind = top.choice("accel", kAccelNames, "accel", scene.accel_kind);
    if (top.has("offset")) {
        const Fields o = top.object("offset");
        scene.offset.method = o.choice("method", kOffsetMethodNames, "offset method", scene.offset.method);
        scene.offset.epsilon = o.length("epsilon", scene.offset.epsilon);
        o.done();
    }
    if (top.has("antialiasing")) {
        const Fields a = top.object("antialiasing");
        scene.antialiasing.pattern = a.choice("pattern", kPatternNames, "pattern", scene.antialiasing.pattern);
        scene.antialiasing.filter = a.choice("filter", kFilterNames, "filter", scene.antialiasing.filter);
        scene.samples = a.integer("samples", limits::samples_per_pixel, 0);
        if (scene.samples && scene.antialiasing.pattern != PixelPattern::random && !pattern_side(scene.samples))
            a.fail("samples", std::string("the ") + kPatternNames[scene.antialiasing.pattern] +
                                  " pattern takes n x n samples (1, 4, 9, 16, ...)");
        a.done();
    }
    scene.background = top.color("background", limits::radiance, scene.background);
    scene.ambient = top.color("ambient", limits::radiance, scene.ambient);

    // Materials by name; only those a surface uses are kept, numbered from 1 (0 is the default).
    std::map<std::string, Material> materials;
    if (top.has("materials"))
        for (const auto& [name, m] : top.named_objects("materials")) materials.emplace(name, read_material(m));
    if (top.has("lights"))
        for (const Fields& l : top.objects("lights")) scene.lights.push_back(read_light(l));
    summary.lights_black = scene.drop_unused_lights();
    summary.lights = int(scene.lights.size());

    // Named shapes, read once and shared by every instance that names them.
    std::map<std::string, std::shared_ptr<const Shape>> shapes;
    std::map<std::string, int> shape_uses;
    std::map<std::string, MaterialId> used;
    const Loader loader{reader, materials, used, scene, shapes, shape_uses};
    if (top.has("shapes")) {
        Loader shapes_loader = loader;
        shapes_loader.in_shapes = true;
        for (const auto& [name, s] : top.named_objects("shapes")) {
            shapes.emplace(name, std::make_shared<const Shape>(read_shape(shapes_loader, s)));
            s.done();
        }
    }

    if (!top.has("surfaces")) top.fail("", "missing key 'surfaces'");
    const std::vector<Fields> ss = top.objects("surfaces");
    top.done();
    for (const Fields& f : ss) {
        bool reused = false;  // a named shape used before
        const std::shared_ptr<const Shape> base = read_entry_shape(loader, f, reused);
        // A mesh's copy shares its triangles; other shapes are copied.
        const std::shared_ptr<const Shape> placed = transformed(f, base);
        Shape shape = *placed;
        if (placed != base)
            ++summary.instances;
        else if (f.has("transform"))
            ++summary.identity_transforms;  // costs nothing per ray: the shape is used as it is
        // Saved memory: a reused shape that is not copied (an instance, or a mesh's shared data).
        if (reused && (std::holds_alternative<Instance>(shape) || std::holds_alternative<Mesh>(shape)))
            summary.shared_bytes += memory_bytes(*base);
        if (!reused) count_triangles(*base, summary);  // stored once, counted once
        const MaterialId material = f.has("material") ? loader.material(f) : 0;
        scene.surfaces.add(std::move(shape), material, f.text("name", ""));
        f.done();
    }
    summary.surfaces = int(ss.size());
    summary.materials = int(used.size());
    summary.materials_unused = int(materials.size() - used.size());
    summary.shapes_unused = int(shapes.size() - shape_uses.size());
    if (summary_out) *summary_out = summary;
    return scene;
}

Scene load_scene_file(const std::string& path, SceneSummary* summary) {
    std::string text;
    try {
        text = read_input_file(path, "scene file", limits::scene_file_bytes);
    } catch (const std::runtime_error& e) {
        throw SceneError(one_line(e.what()));
    }
    const std::string dir = std::filesystem::path(path).parent_path().string();
    return load_scene_text(text, path, dir.empty() ? "." : dir, summary);
}

}  // namespace rt
