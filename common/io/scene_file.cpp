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
    f.only({"projection", "eye", "target", "up", "fov", "window_height", "focal_distance", "aperture", "focus_distance",
            "lens", "shutter"});
    Camera cam;
    const std::string projection = f.text("projection", "perspective");
    if (projection == "orthographic")
        cam.projection = Projection::orthographic;
    else if (projection != "perspective")
        f.fail("projection", "must be \"perspective\" or \"orthographic\", not \"" + projection + "\"");
    cam.eye = f.vec3("eye");
    cam.target = f.vec3("target");
    cam.up = f.vec3("up", cam.up);
    cam.vertical_fov_degrees = f.number("fov", limits::field_of_view, cam.vertical_fov_degrees);
    cam.window_height = f.length("window_height", cam.window_height);
    cam.focal_distance = f.length("focal_distance", cam.focal_distance);
    // Chapter 16: a thin lens; chapter 18: the shutter interval.
    cam.aperture = f.number("aperture", limits::aperture, cam.aperture);
    cam.focus_distance = f.length("focus_distance", cam.focus_distance);
    const std::string lens = f.text("lens", "square");
    if (lens == "disk")
        cam.lens = LensShape::disk;
    else if (lens != "square")
        f.fail("lens", "must be \"square\" or \"disk\", not \"" + lens + "\"");
    if ((f.has("focus_distance") || f.has("lens")) && !(cam.aperture > 0))
        f.fail(f.has("lens") ? "lens" : "focus_distance", "a lens needs an aperture > 0");
    if (f.has("shutter")) {
        const json& v = f.value()["shutter"];
        if (!v.is_array() || v.size() != 2) f.fail("shutter", "must be [open, close], two times in [0, 1]");
        const auto at = [&](std::size_t k) {
            if (!v[k].is_number()) f.fail("shutter", "must be [open, close], two times in [0, 1]");
            const double x = v[k].get<double>();
            if (!limits::contains(limits::shutter, x)) f.fail("shutter", limits::refuse(limits::shutter, x));
            return Real(x);
        };
        cam.shutter_open = at(0);
        cam.shutter_close = at(1);
        if (!(cam.shutter_open <= cam.shutter_close)) f.fail("shutter", "closes before it opens");
    }
    try {
        cam.validate();
    } catch (const std::invalid_argument& e) {
        f.fail("", e.what());
    }
    return cam;
}

Light read_light(const Fields& f) {
    const std::string type = f.text("type");
    for (const LightType& t : light_types()) {
        if (type != t.name) continue;
        std::vector<const char*> keys = {"type", "color"};
        keys.insert(keys.end(), t.keys.begin(), t.keys.end());
        f.only(keys);
        Light light = t.read(f);
        light.color = f.color("color", limits::radiance, light.color);
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

// The shape of one /surfaces (or /shapes) entry, by its type's module. Keys every type
// takes: "smooth" (meshes only) gives a mesh vertex normals for smooth shading.
Shape read_shape(const Loader& loader, const Fields& f, std::vector<const char*> common) {
    const std::string type = f.text("type");
    if (type == "csg") {
        common.insert(common.end(), {"type", "op", "operands", "thin"});
        f.only(common);
        return read_csg(loader, f);
    }
    for (const SurfaceType& t : surface_types()) {
        if (type != t.name) continue;
        common.push_back("type");
        common.push_back("smooth");
        common.insert(common.end(), t.keys.begin(), t.keys.end());
        f.only(common);
        try {
            Shape shape = t.read(f);
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
    std::shared_ptr<const Shape> base;
    if (f.text("type") == "instance") {
        f.only({"type", "name", "material", "shape", "transform"});
        if (loader.in_shapes)
            f.fail("type", "an operand of a shape in /shapes cannot name another shape; give the operand itself");
        const std::string name = f.text("shape");
        const auto it = loader.shapes.find(name);
        if (it == loader.shapes.end()) f.fail("shape", "no shape named \"" + name + "\" in /shapes");
        ++loader.shape_uses[name];
        base = it->second;
    } else {
        base = std::make_shared<const Shape>(read_shape(loader, f, {"name", "material", "transform"}));
    }
    const std::string why = not_solid(*base);
    if (!why.empty()) {
        const std::string name = f.text("name", "");
        f.fail("", "a CSG operand must be a closed solid: " + (name.empty() ? "" : "'" + name + "': ") + why);
    }
    CsgOperand operand{transformed(f, base), kNone, f.text("name", "")};
    if (f.has("material")) operand.material = loader.material(f);
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
    const std::string name = f.text("op");
    CsgOp op{};
    bool known = false;
    for (CsgOp o : {CsgOp::union_of, CsgOp::intersection, CsgOp::difference})
        if (name == csg_op_name(o)) op = o, known = true;
    if (!known) f.fail("op", "unknown CSG operation \"" + name + "\" (expected union, intersection or difference)");
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

Scene load_scene_text(const std::string& text, const std::string& filename, const std::string& base_dir,
                      SceneSummary* summary_out) {
    const json doc = parse(text, filename);
    const JsonReader reader(text, filename, base_dir);
    const Fields top(reader, doc, "");
    top.only({"$schema", "description", "camera", "shading", "background", "ambient", "max_depth", "offset", "accel",
              "antialiasing", "materials", "lights", "shapes", "surfaces"});
    SceneSummary summary;
    summary.from_file = true;
    Scene scene;
    scene.description = top.text("description", "");
    if (!top.has("camera")) top.fail("", "missing key 'camera'");
    scene.camera = read_camera(Fields(reader, doc["camera"], "/camera"));
    const std::string shading = top.text("shading", "phong");
    scene.integrator = make_integrator(shading);
    if (!scene.integrator)
        top.fail("shading", "unknown shading \"" + shading +
                                "\" (expected phong, whitted, normal, barycentric, direction or cost)");
    scene.max_depth = top.integer("max_depth", limits::recursion_depth, scene.max_depth);
    const std::string accel = top.text("accel", accel_name(scene.accel_kind));
    if (const auto kind = accel_kind(accel))
        scene.accel_kind = *kind;
    else
        top.fail("accel", "unknown accel \"" + accel + "\" (expected " + accel_names() + ")");
    if (top.has("offset")) {
        const Fields o(reader, doc["offset"], "/offset");
        o.only({"method", "epsilon"});
        const std::string method = o.text("method", "robust");
        bool known = false;
        for (int k = 0; k < 3; ++k)
            if (method == kOffsetMethodNames[k]) scene.offset.method = OffsetMethod(k), known = true;
        if (!known) o.fail("method", "unknown offset method \"" + method + "\" (expected robust, course or normal)");
        scene.offset.epsilon = o.length("epsilon", scene.offset.epsilon);
    }
    if (top.has("antialiasing")) {
        const Fields a(reader, doc["antialiasing"], "/antialiasing");
        a.only({"pattern", "filter", "samples"});
        const std::string pattern = a.text("pattern", pattern_name(scene.antialiasing.pattern));
        if (const auto p = pixel_pattern(pattern))
            scene.antialiasing.pattern = *p;
        else
            a.fail("pattern", "unknown pattern \"" + pattern + "\" (expected random, regular or jittered)");
        const std::string filter = a.text("filter", filter_name(scene.antialiasing.filter));
        if (const auto f = pixel_filter(filter))
            scene.antialiasing.filter = *f;
        else
            a.fail("filter", "unknown filter \"" + filter + "\" (expected box or tent)");
        scene.samples = a.integer("samples", limits::samples_per_pixel, 0);
        if (scene.samples && scene.antialiasing.pattern != PixelPattern::random && !pattern_side(scene.samples))
            a.fail("samples", "the " + pattern + " pattern takes n x n samples (1, 4, 9, 16, ...)");
    }
    scene.background = top.color("background", limits::radiance, scene.background);
    scene.ambient = top.color("ambient", limits::radiance, scene.ambient);

    // Materials by name; only those a surface uses are kept, numbered from 1 (0 is the default).
    std::map<std::string, Material> materials;
    if (top.has("materials")) {
        const Fields ms(reader, doc["materials"], "/materials");
        for (const auto& [name, m] : doc["materials"].items())
            materials.emplace(name, read_material(Fields(reader, m, "/materials/" + name)));
    }
    if (top.has("lights")) {
        const json& ls = doc["lights"];
        if (!ls.is_array()) top.fail("lights", "must be an array");
        for (std::size_t i = 0; i < ls.size(); ++i)
            scene.lights.push_back(read_light(Fields(reader, ls[i], "/lights/" + std::to_string(i))));
    }
    summary.lights_black = scene.drop_unused_lights();
    summary.lights = int(scene.lights.size());

    // Named shapes, read once and shared by every instance that names them.
    std::map<std::string, std::shared_ptr<const Shape>> shapes;
    std::map<std::string, int> shape_uses;
    std::map<std::string, MaterialId> used;
    const Loader loader{reader, materials, used, scene, shapes, shape_uses};
    if (top.has("shapes")) {
        const Fields all(reader, doc["shapes"], "/shapes");
        Loader shapes_loader = loader;
        shapes_loader.in_shapes = true;
        for (const auto& [name, s] : doc["shapes"].items())
            shapes.emplace(name, std::make_shared<const Shape>(
                                     read_shape(shapes_loader, Fields(reader, s, "/shapes/" + name), {})));
    }

    if (!top.has("surfaces")) top.fail("", "missing key 'surfaces'");
    const json& ss = doc["surfaces"];
    if (!ss.is_array()) top.fail("surfaces", "must be an array");
    for (std::size_t i = 0; i < ss.size(); ++i) {
        const Fields f(reader, ss[i], "/surfaces/" + std::to_string(i));
        std::shared_ptr<const Shape> base;
        bool reused = false;  // a named shape used before
        if (f.text("type") == "instance") {
            f.only({"type", "name", "material", "shape", "transform"});
            const std::string name = f.text("shape");
            const auto it = shapes.find(name);
            if (it == shapes.end()) f.fail("shape", "no shape named \"" + name + "\" in /shapes");
            base = it->second;
            reused = shape_uses[name]++ > 0;
        } else {
            base = std::make_shared<const Shape>(read_shape(loader, f, {"name", "material", "transform"}));
        }
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
