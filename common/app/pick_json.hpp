#pragma once
// What --pick prints: the picked surface, t, point, normal (beta and gamma on a triangle) and
// the ray tree, as JSON. One writer for the command line and the explorer's clicks.
#include "render/render.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace rt {

nlohmann::json pick_json(const std::string& scene_name, const Scene& scene, int x, int y, const Pick& p);

// Names come from file names, which need not be UTF-8: such bytes print as U+FFFD rather
// than make the dump throw.
std::string dump(const nlohmann::json& j);

}  // namespace rt
