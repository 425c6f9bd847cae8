#include "app/app.hpp"

#include "core/version.hpp"
#include "io/image_file.hpp"
#include "render/render.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <unistd.h>
#include <cstdio>
#include <iostream>

namespace rt {

namespace {

using nlohmann::json;

json to_json(const Vec3& v) {
    return json::array({v.x, v.y, v.z});
}

json pick_json(const SceneEntry& entry, const Scene& scene, int x, int y, const Pick& p) {
    json j{{"scene", entry.name},
           {"pixel", {x, y}},
           {"ray", {{"origin", to_json(p.ray.origin)}, {"direction", to_json(p.ray.direction)}}},
           {"hit", p.hit.has_value()}};
    if (p.hit) {
        const HitRecord& h = *p.hit;
        j["surface"] = h.surface < scene.surfaces.size() ? scene.surfaces.name(h.surface) : "";
        j["t"] = h.t;
        j["point"] = to_json(h.p);
        j["normal"] = to_json(h.normal);
        if (h.primitive != kNone) j["triangle"] = h.primitive;
        if (h.has_barycentrics) {
            j["beta"] = h.beta;
            j["gamma"] = h.gamma;
        }
    }
    return j;
}

json stats_json(const std::string& chapter, const SceneEntry& entry, const RenderOptions& o, const RenderResult& r,
                const SceneSummary& s) {
    const double mrays = r.seconds > 0 ? double(r.counters.total()) / r.seconds / 1e6 : 0.0;
    json rays{{"total", r.counters.total()}};
    for (std::size_t k = 0; k < kRayKinds; ++k) rays[kRayKindNames[k]] = r.counters.rays[k];
    json j{{"chapter", chapter},
           {"scene", entry.name},
           {"width", o.width},
           {"height", o.height},
           {"spp", o.spp},
           {"threads", r.threads},
           {"real", real_name()},
           {"track", RTLAB_TRACK_NAME},
           {"from_solutions", RTLAB_SOLVED_TEXT},
           {"rays", rays},
           {"shading", {{"light_terms", r.counters.light_terms}, {"specular_terms", r.counters.specular_terms}}},
           {"seconds", r.seconds},
           {"mrays_per_s", mrays}};
    if (s.from_file) {  // what loading the scene file kept, and what it left out
        j["scene_kept"] = {
            {"surfaces", s.surfaces}, {"triangles", s.triangles}, {"lights", s.lights}, {"materials", s.materials}};
        j["scene_skipped"] = {{"black_lights", s.lights_black},
                              {"unused_materials", s.materials_unused},
                              {"degenerate_triangles", s.degenerate_triangles}};
    }
    return j;
}

}  // namespace

int ChapterApp::run(int argc, char** argv) const {
    CLI::App cli{id_ + ": " + title_, id_};
    RenderOptions o;
    std::string scene_name = scenes_.empty() ? "" : scenes_.front().name;
    std::string output;
    std::vector<int> pick_xy;
    bool list = false, stats = false;

    // A whole number first, then its range: "--width abc" is told it is not a number.
    const CLI::Validator whole(
        [](std::string& value) {
            std::size_t used = 0;
            try {
                (void)std::stoll(value, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            return used > 0 && used == value.size() ? std::string() : "must be a whole number, not '" + value + "'";
        },
        "");
    cli.add_option("--width", o.width, "image width in pixels")
        ->check(whole)
        ->check(CLI::Range(1, 16384))
        ->capture_default_str();
    cli.add_option("--height", o.height, "image height in pixels")
        ->check(whole)
        ->check(CLI::Range(1, 16384))
        ->capture_default_str();
    cli.add_option("--spp", o.spp, "samples per pixel (1 = the pixel centre)")
        ->check(whole)
        ->check(CLI::Range(1, 65536))
        ->capture_default_str();
    cli.add_option("--seed", o.seed, "random seed (images are identical for equal seeds)")->capture_default_str();
    cli.add_option("--threads", o.threads, "worker threads, 0 = all cores")
        ->check(whole)
        ->check(CLI::Range(0, 1024))
        ->capture_default_str();
    cli.add_option("-o,--output", output,
                   "output image, .png (sRGB) or .pfm (linear float); default out/" + id_ + "/SCENE.png");
    cli.add_option("--scene", scene_name, "a built-in scene (see --list-scenes) or a scene file FILE.json")
        ->capture_default_str();
    cli.add_flag("--list-scenes", list, "print the scene names, one a line, and exit");
    cli.add_option("--pick", pick_xy, "print what pixel X,Y (from the top left) sees, as JSON, and exit")
        ->delimiter(',')
        ->expected(2);
    cli.add_flag("--stats", stats, "print render statistics as one JSON line");
    cli.set_version_flag("--version",
                         std::string(id_ + " (rtlab " + kVersion + ", Real=" + real_name() + ", " + RTLAB_TRACK_NAME +
                                     " track, exercises from solutions/: " + RTLAB_SOLVED_TEXT + ")"));

    try {
        cli.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return cli.exit(e);  // --help, --version
        std::fprintf(stderr, "%s: error: %s\n", id_.c_str(), e.what());
        return 2;
    }

    if (list) {
        for (const SceneEntry& s : scenes_) std::printf("%s\n", s.name.c_str());
        return 0;
    }
    const SceneEntry* entry = nullptr;
    for (const SceneEntry& s : scenes_)
        if (s.name == scene_name) entry = &s;
    SceneEntry file_entry;
    if (!entry && scene_name.size() > 5 && scene_name.ends_with(".json")) {
        std::string stem = scene_name.substr(scene_name.find_last_of('/') + 1);
        stem = stem.substr(0, stem.size() - 5);
        file_entry = {stem, "scene file " + scene_name,
                      [path = scene_name](SceneSummary& summary) { return load_scene_file(path, &summary); }};
        entry = &file_entry;
    }
    if (!entry) {
        std::fprintf(stderr, "%s: error: --scene: unknown scene '%s' (see --list-scenes, or give a FILE.json)\n",
                     id_.c_str(), scene_name.c_str());
        return 2;
    }
    if (output.empty()) output = "out/" + id_ + "/" + entry->name + ".png";
    if (!is_image_path(output)) {
        std::fprintf(stderr, "%s: error: --output: '%s' must end in .png or .pfm\n", id_.c_str(), output.c_str());
        return 2;
    }

    try {
        SceneSummary summary;
        Scene scene = entry->build(summary);
        scene.name = entry->name;
        if (!pick_xy.empty()) {
            const Pick p = pick(scene, o, pick_xy[0], pick_xy[1]);
            std::printf("%s\n", pick_json(*entry, scene, pick_xy[0], pick_xy[1], p).dump().c_str());
            return 0;
        }
        o.progress = ::isatty(STDERR_FILENO) != 0;
        const RenderResult r = render(scene, o);
        write_image(r.image, output);
        if (stats) std::printf("%s\n", stats_json(id_, *entry, o, r, summary).dump().c_str());
    } catch (const std::exception& e) {
        // Bad input (a scene file, a camera, a value) is exit 2; a render that failed, exit 1.
        const bool bad_input = dynamic_cast<const SceneError*>(&e) || dynamic_cast<const std::invalid_argument*>(&e);
        std::fprintf(stderr, "%s: error: %s\n", id_.c_str(), e.what());
        return bad_input ? 2 : 1;
    }
    return 0;
}

}  // namespace rt
