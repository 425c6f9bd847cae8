#pragma once
// JSON scene files (book appendix A). Every chapter executable takes one as --scene FILE.json.
#include "io/file_access.hpp"
#include "io/json_reader.hpp"
#include "render/scene.hpp"

#include <string>

namespace rt {

// What loading kept and what it left out, for --stats.
struct SceneSummary {
    bool from_file = false;
    int surfaces = 0;
    int materials = 0;
    int materials_unused = 0;  // defined but used by no surface: not kept
    int lights = 0;
    int lights_black = 0;  // colour (0,0,0): dropped, never evaluated
    std::uint64_t triangles = 0;
    std::uint64_t degenerate_triangles = 0;  // zero-area mesh triangles: dropped
    int instances = 0;                       // surfaces that see a shape through a transform
    int identity_transforms = 0;             // transforms that do nothing: no instance made
    int shapes_unused = 0;                   // in /shapes but named by no instance
    // What instancing saved: the bytes of the shapes that instances (and named shapes used
    // more than once) share instead of holding copies.
    std::uint64_t shared_bytes = 0;
};

// Throws SceneError. Relative mesh paths are relative to the scene file's directory. A scene
// file may name any file; a scene's text, only the files `access` lets it (the explorer's
// scenes sent over HTTP).
Scene load_scene_file(const std::string& path, SceneSummary* summary = nullptr);
Scene load_scene_text(const std::string& text, const std::string& filename, const std::string& base_dir,
                      SceneSummary* summary = nullptr, const FileAccess& access = {});
// A scene file's "camera" object on its own (the explorer's camera moves), read as the
// loader reads it. Throws SceneError.
Camera load_camera_text(const std::string& text, const std::string& filename);

}  // namespace rt
