#pragma once
// The command line every chapter executable shares. A chapter's main() registers its scenes
// and calls run(); everything else (options, rendering, output, picking, stats) is here.
#include "io/scene_file.hpp"
#include "render/scene.hpp"

#include <functional>
#include <string>
#include <vector>

namespace rt {

struct SceneEntry {
    std::string name;
    std::string description;
    std::function<Scene(SceneSummary&)> build;
};

class ChapterApp {
public:
    ChapterApp(std::string id, std::string title) : id_(std::move(id)), title_(std::move(title)) {}

    void add_scene(std::string name, std::string description, std::function<Scene()> build) {
        scenes_.push_back(
            {std::move(name), std::move(description), [b = std::move(build)](SceneSummary&) { return b(); }});
    }
    // A scene kept as a JSON file beside the chapter (see chapters/*/scenes/).
    void add_scene_file(std::string name, std::string path) {
        scenes_.push_back({std::move(name), "scene file " + path,
                           [path](SceneSummary& summary) { return load_scene_file(path, &summary); }});
    }

    // --scene takes a registered name or any FILE.json. Exit codes: 0 done, 1 the render
    // failed (e.g. an unfinished exercise or an unwritable output), 2 bad input (command line
    // or scene file).
    int run(int argc, char** argv) const;

private:
    std::string id_;
    std::string title_;
    std::vector<SceneEntry> scenes_;
};

}  // namespace rt
