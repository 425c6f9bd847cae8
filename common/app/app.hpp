#pragma once
// The command line every chapter executable shares. A chapter's main() registers its scenes
// and calls run(); everything else (options, rendering, output, picking, stats) is here.
#include "app/lab_paths.hpp"  // chapter_dir(), for a chapter's add_scene_files
#include "io/scene_file.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"

#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

namespace rt {

struct SceneEntry {
    std::string name;
    std::string description;
    std::function<Scene(SceneSummary&)> build;
    std::string file;  // the scene file it loads, or empty for a scene made in code
};

class ChapterApp {
public:
    ChapterApp(std::string id, std::string title) : id_(std::move(id)), title_(std::move(title)) {}

    void add_scene(std::string name, std::string description, std::function<Scene()> build) {
        scenes_.push_back(
            {std::move(name), std::move(description), [b = std::move(build)](SceneSummary&) { return b(); }, ""});
    }
    // Scenes kept as files NAME.json in the chapter's folder `chapter_dir`/scenes/.
    void add_scene_files(const std::string& chapter_dir, std::initializer_list<const char*> names) {
        for (const char* name : names) add_scene_file(name, chapter_dir + "/scenes/" + name + ".json");
    }
    // A scene kept as a JSON file beside the chapter (see chapters/*/scenes/).
    void add_scene_file(std::string name, std::string path) {
        scenes_.push_back({std::move(name), "scene file " + path,
                           [path](SceneSummary& summary) { return load_scene_file(path, &summary); }, path});
    }

    // --scene takes a registered name or any FILE.json. Exit codes: 0 done, 1 the render
    // failed (e.g. an unfinished exercise or an unwritable output), 2 bad input (command line
    // or scene file); a run ended by SIGINT or SIGTERM ends by that signal (130 or 143 in a
    // shell). A run that fails writes no file.
    int run(int argc, char** argv) const;

    // What a command line asks for, once parsed and checked.
    struct Invocation {
        RenderOptions options;
        SceneEntry scene;
        std::string output;
        std::vector<int> pick;         // empty, or X and Y
        std::string svg;               // with pick: draw the ray tree into this file
        std::optional<int> max_depth;  // --depth: overrides the scene's
        std::string accel;             // --accel: overrides the scene's (empty: the scene's)
        std::string pattern, filter;   // --pattern, --filter: override the scene's antialiasing
        bool spp_given = false;        // --spp overrides the scene's samples
        bool stats = false;
        bool explore = false;  // --explore: serve the explorer (common/app/explore.hpp) instead
        int port = 0;          // --port: its port on 127.0.0.1 (0: any free one)
        // --allow DIR: folders whose files a scene sent by the explorer's page may name,
        // besides scene_folders() and the lab's shared assets (book §0.11).
        std::vector<std::string> allow;
        bool no_token = false;  // --no-token: the explorer asks no token (for tests only)
    };
    // Parses and checks a command line without touching any file: the exit code to end with
    // (--help, --version, --list-scenes, or 2 after one line on stderr), or nothing when
    // `invocation` is ready for execute().
    // With `message`, that line goes there instead (the explorer's settings are command-line
    // options: one reader checks both).
    std::optional<int> parse(int argc, const char* const* argv, Invocation& invocation,
                             std::string* message = nullptr) const;
    int execute(const Invocation& invocation) const;

    const std::string& id() const { return id_; }
    const std::string& title() const { return title_; }
    const std::vector<SceneEntry>& scenes() const { return scenes_; }
    // The folders of the chapter's own scene files (chapters/chNN_*/scenes/), once each.
    std::vector<std::string> scene_folders() const;

private:
    std::string id_;
    std::string title_;
    std::vector<SceneEntry> scenes_;
};

}  // namespace rt
