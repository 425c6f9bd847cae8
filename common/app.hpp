#pragma once
// The command line every chapter executable shares. A chapter's main() registers its scenes
// and calls run(); everything else (options, rendering, output, picking, stats) is here.
#include "common/scene.hpp"

#include <functional>
#include <string>
#include <vector>

namespace rt {

struct SceneEntry {
    std::string name;
    std::string description;
    std::function<Scene()> build;
};

class ChapterApp {
public:
    ChapterApp(std::string id, std::string title) : id_(std::move(id)), title_(std::move(title)) {}

    void add_scene(std::string name, std::string description, std::function<Scene()> build) {
        scenes_.push_back({std::move(name), std::move(description), std::move(build)});
    }

    // Exit codes: 0 done, 1 the render failed (e.g. an unfinished exercise or an unwritable
    // output), 2 bad command-line input.
    int run(int argc, char** argv) const;

private:
    std::string id_;
    std::string title_;
    std::vector<SceneEntry> scenes_;
};

}  // namespace rt
