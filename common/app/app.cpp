#include "app/app.hpp"

#include "app/explore.hpp"
#include "app/pick_json.hpp"
#include "app/ray_tree_svg.hpp"
#include "core/build_info.hpp"
#include "core/exercise.hpp"
#include "core/text.hpp"
#include "geometry/limits.hpp"
#include "io/image_file.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <unistd.h>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace rt {

namespace {

using nlohmann::json;

json accel_json(const Scene& scene) {
    if (!scene.accel) return nullptr;
    const AccelInfo& a = scene.accel->info();
    return {{"kind", kAccelNames[a.kind]},
            {"build_seconds", a.build_seconds},
            {"primitives", a.primitives},
            {"nodes", a.nodes},
            {"depth", a.depth},
            {"bytes", a.bytes},
            {"bytes_per_primitive", a.primitives ? double(a.bytes) / double(a.primitives) : 0.0}};
}

json stats_json(const std::string& chapter, const SceneEntry& entry, const Scene& scene, const RenderOptions& o,
                const RenderResult& r, const SceneSummary& s) {
    const auto per_ray = [&](std::uint64_t n) {
        return r.counters.total() ? double(n) / double(r.counters.total()) : 0.0;
    };
    const double mrays = r.seconds > 0 ? double(r.counters.total()) / r.seconds / 1e6 : 0.0;
    json rays{{"total", r.counters.total()}};
    for (std::size_t k = 0; k < kRayKinds; ++k) rays[kRayKindNames[RayKind(k)]] = r.counters.rays[k];
    // Random numbers drawn per dimension: zero for every effect the scene does not use.
    json draws;
    for (std::size_t d = 0; d < kDimensions; ++d) draws[kDimensionNames[Dimension(d)]] = r.counters.draws[d];
    json j{{"chapter", chapter},
           {"scene", entry.name},
           {"width", o.width},
           {"height", o.height},
           {"spp", o.spp},
           {"pattern", kPatternNames[o.antialiasing.pattern]},
           {"filter", kFilterNames[o.antialiasing.filter]},
           {"threads", r.threads},
           {"real", real_name()},
           {"track", build_info::track},
           {"from_solutions", build_info::from_solutions},
           // The student's exercises this render went through (the grader names them when a
           // golden image fails; core/exercise.hpp): "" in the solutions track.
           {"your_exercises", exercise_use::list()},
           {"rays", rays},
           {"random_numbers", draws},
           {"shading", {{"light_terms", r.counters.light_terms}, {"specular_terms", r.counters.specular_terms}}},
           {"nonfinite_samples", r.counters.nonfinite_samples},
           {"accel", accel_json(scene)},
           {"search",
            {{"nodes_visited", r.counters.nodes_visited},
             {"primitives_tested", r.counters.primitives_tested},
             {"nodes_per_ray", per_ray(r.counters.nodes_visited)},
             {"primitives_per_ray", per_ray(r.counters.primitives_tested)}}},
           {"seconds", r.seconds},
           {"mrays_per_s", mrays}};
    if (s.from_file) {  // what loading the scene file kept, and what it left out
        j["scene_kept"] = {
            {"surfaces", s.surfaces}, {"triangles", s.triangles}, {"lights", s.lights}, {"materials", s.materials}};
        j["scene_skipped"] = {{"black_lights", s.lights_black},
                              {"unused_materials", s.materials_unused},
                              {"degenerate_triangles", s.degenerate_triangles},
                              {"identity_transforms", s.identity_transforms},
                              {"unused_shapes", s.shapes_unused}};
        j["instancing"] = {{"instances", s.instances}, {"shared_bytes", s.shared_bytes}};
    }
    return j;
}

}  // namespace

std::optional<int> ChapterApp::parse(int argc, const char* const* argv, Invocation& inv, std::string* message) const {
    CLI::App cli{id_ + ": " + title_, id_};
    RenderOptions& o = inv.options;
    std::string scene_name = scenes_.empty() ? "" : scenes_.front().name;
    bool list = false;

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
    const auto range = [](const limits::Range& r) { return CLI::Range(r.min, r.max); };
    cli.add_option("--width", o.width, "image width in pixels")
        ->check(whole)
        ->check(range(limits::image_side))
        ->capture_default_str();
    cli.add_option("--height", o.height, "image height in pixels")
        ->check(whole)
        ->check(range(limits::image_side))
        ->capture_default_str();
    cli.add_option("--spp", o.spp,
                   "samples per pixel (default: the scene's, else 1; one random sample with the box filter is the "
                   "pixel centre)")
        ->check(whole)
        ->check(range(limits::samples_per_pixel))
        ->capture_default_str();
    cli.add_option("--seed", o.seed, "random seed (images are identical for equal seeds)")
        ->check(whole)
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    cli.add_option("--threads", o.threads, "worker threads, 0 = all cores")
        ->check(whole)
        ->check(range(limits::threads))
        ->capture_default_str();
    cli.add_option("-o,--output", inv.output,
                   "output image, .png (sRGB) or .pfm (linear float); default out/" + id_ + "/SCENE.png");
    cli.add_option("--scene", scene_name, "a built-in scene (see --list-scenes) or a scene file FILE.json")
        ->capture_default_str();
    cli.add_flag("--list-scenes", list, "print the scene names, one a line, and exit");
    cli.add_option("--pick", inv.pick, "print what pixel X,Y (from the top left) sees, as JSON, and exit")
        ->delimiter(',')
        ->expected(2);
    cli.add_option("--svg", inv.svg, "with --pick: also draw the pixel's ray tree into FILE.svg");
    cli.add_option("--depth", inv.max_depth,
                   "maximum recursion depth of reflection and refraction (default: the scene's)")
        ->check(whole)
        ->check(range(limits::recursion_depth));
    // A name of an enum (core/names.hpp), refused with the list of names.
    const auto one_of = [](const auto& names) {
        return CLI::Validator(
            [names](std::string& value) {
                return names.find(value) ? std::string() : "unknown '" + value + "' (expected " + names.list() + ")";
            },
            "");
    };
    cli.add_option("--accel", inv.accel,
                   "search structure: " + kAccelNames.list() + " (default: the scene's, else " +
                       kAccelNames[Scene{}.accel_kind] + ")")
        ->check(one_of(kAccelNames));
    cli.add_option("--pattern", inv.pattern,
                   "where pixel samples go: " + kPatternNames.list() + " (default: the scene's)")
        ->check(one_of(kPatternNames));
    cli.add_option("--filter", inv.filter,
                   "how samples are weighed: " + kFilterNames.list() + " (default: the scene's)")
        ->check(one_of(kFilterNames));
    cli.add_flag("--stats", inv.stats, "print render statistics as one JSON line");
    cli.add_flag("--explore", inv.explore,
                 "serve the lab explorer on 127.0.0.1 and print its address: a progressive render of the scene "
                 "in a browser page, its camera moved by the mouse, any pixel's ray tree on a click (default size "
                 "640x360)");
    cli.add_option("--port", inv.port, "with --explore: the port to serve on (0: any free one)")
        ->check(whole)
        ->check(CLI::Range(0, 65535))
        ->capture_default_str();
    cli.add_option("--allow", inv.allow,
                   "with --explore: a folder whose files a scene sent by the page may name, besides the chapter's "
                   "scenes and ../shared/assets (again for another)")
        ->check(CLI::ExistingDirectory)
        ->allow_extra_args(false);
    cli.add_flag("--no-token", inv.no_token,
                 "with --explore: ask no token, so that any program on this machine may drive it (for tests only)");
    cli.set_version_flag("--version", std::string(id_ + " (rtlab " + build_info::version + ", Real=" + real_name() +
                                                  ", " + build_info::track + " track, exercises from solutions/: " +
                                                  build_info::from_solutions + ")"));

    const auto usage = [&](const std::string& what) {
        if (message)
            *message = one_line(what);
        else
            std::fprintf(stderr, "%s: error: %s\n", id_.c_str(), one_line(what).c_str());
        return 2;
    };
    try {
        cli.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return cli.exit(e);  // --help, --version
        return usage(e.what());
    }

    if (list) {
        for (const SceneEntry& s : scenes_) std::printf("%s\n", s.name.c_str());
        return 0;
    }
    const SceneEntry* entry = nullptr;
    for (const SceneEntry& s : scenes_)
        if (s.name == scene_name) entry = &s;
    if (entry) {
        inv.scene = *entry;
    } else if (scene_name.size() > 5 && scene_name.ends_with(".json")) {
        std::string stem = scene_name.substr(scene_name.find_last_of('/') + 1);
        stem = stem.substr(0, stem.size() - 5);
        inv.scene = {stem, "scene file " + scene_name,
                     [path = scene_name](SceneSummary& summary) { return load_scene_file(path, &summary); },
                     scene_name};
    } else {
        return usage("--scene: unknown scene '" + scene_name + "' (see --list-scenes, or give a FILE.json)");
    }
    inv.spp_given = cli.count("--spp") > 0;
    for (const char* option : {"--port", "--allow", "--no-token"})
        if (cli.count(option) && !inv.explore)
            return usage(std::string(option) + ": an option of the explorer, so it needs --explore");
    if (inv.explore) {  // the explorer's own default size: 16:9, quick enough to move
        if (!cli.count("--width")) o.width = 640;
        if (!cli.count("--height")) o.height = 360;
        if (!inv.pick.empty() || cli.count("--output") || inv.stats)
            return usage("--explore: serves a page; --pick, --output and --stats are for a single render");
    }
    if (!inv.pattern.empty()) o.antialiasing.pattern = *kPatternNames.find(inv.pattern);
    if (cli.count("--output") && inv.output.empty()) return usage("--output: must not be empty");
    if (cli.count("--svg")) {
        if (inv.pick.empty()) return usage("--svg: draws a picked pixel's ray tree, so it needs --pick X,Y");
        if (inv.svg.size() < 5 || !inv.svg.ends_with(".svg") || inv.svg.ends_with("/.svg"))
            return usage("--svg: '" + inv.svg + "' must end in .svg");
    }
    if (inv.output.empty()) inv.output = "out/" + id_ + "/" + inv.scene.name + ".png";
    if (!is_image_path(inv.output)) return usage("--output: '" + inv.output + "' must end in .png or .pfm");
    try {  // the library's own checks, before any work
        check_budget(o);
        if (!inv.pick.empty()) check_pick(o, inv.pick[0], inv.pick[1]);
    } catch (const std::invalid_argument& e) {
        return usage(e.what());
    }
    return std::nullopt;
}

std::vector<std::string> ChapterApp::scene_folders() const {
    std::vector<std::string> folders;
    for (const SceneEntry& s : scenes_) {
        const std::string folder = std::filesystem::path(s.file).parent_path().string();
        if (!s.file.empty() && std::find(folders.begin(), folders.end(), folder) == folders.end())
            folders.push_back(folder);
    }
    return folders;
}

int ChapterApp::execute(const Invocation& inv) const {
    if (inv.explore) return explore(*this, inv);
    try {
        SceneSummary summary;
        Scene scene = inv.scene.build(summary);
        scene.name = inv.scene.name;
        if (inv.max_depth) scene.max_depth = *inv.max_depth;
        scene.build_accel(inv.accel.empty() ? scene.accel_kind : *kAccelNames.find(inv.accel));
        if (!inv.pick.empty()) {
            const Pick p = pick(scene, inv.options, inv.pick[0], inv.pick[1]);
            const std::string text = dump(pick_json(inv.scene.name, scene, inv.pick[0], inv.pick[1], p));
            if (!inv.svg.empty() && p.tree.nodes.empty())
                throw std::invalid_argument("--svg: scene '" + inv.scene.name +
                                            "' is shaded without a ray tree; use \"shading\": \"whitted\"");
            if (!inv.svg.empty())
                write_file_atomically(inv.svg, ray_tree_svg(scene, p.tree,
                                                            inv.scene.name + ", pixel " + std::to_string(inv.pick[0]) +
                                                                "," + std::to_string(inv.pick[1]),
                                                            p.color));
            std::printf("%s\n", text.c_str());
            return 0;
        }
        RenderOptions o = inv.options;
        o.progress = ::isatty(STDERR_FILENO) != 0;
        o.antialiasing = scene.antialiasing;
        if (!inv.pattern.empty()) o.antialiasing.pattern = *kPatternNames.find(inv.pattern);
        if (!inv.filter.empty()) o.antialiasing.filter = *kFilterNames.find(inv.filter);
        if (!inv.spp_given && scene.samples > 0) o.spp = scene.samples;
        const RenderResult r = render(scene, o);
        // Everything that can fail happens before the image is written, so a failed run
        // leaves no file.
        const std::string stats = inv.stats ? dump(stats_json(id_, inv.scene, scene, o, r, summary)) : "";
        write_image(r.image, inv.output);
        if (inv.stats) std::printf("%s\n", stats.c_str());
    } catch (const std::exception& e) {
        // Bad input (a scene file, a camera, a value) is exit 2; a render that failed, exit 1.
        const bool bad_input = dynamic_cast<const SceneError*>(&e) || dynamic_cast<const std::invalid_argument*>(&e);
        std::fprintf(stderr, "%s: error: %s\n", id_.c_str(), one_line(e.what()).c_str());
        return bad_input ? 2 : 1;
    }
    return 0;
}

int ChapterApp::run(int argc, char** argv) const {
    Invocation invocation;
    if (const auto code = parse(argc, argv, invocation)) return *code;
    remove_temporaries_on_interrupt();
    return execute(invocation);
}

}  // namespace rt
