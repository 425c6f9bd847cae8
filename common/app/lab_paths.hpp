#pragma once
#include <string>

namespace rt {

// Where the lab's own files are on this machine. Only lab_paths.cpp knows these absolute
// paths (CMake gives them to that file alone), so every other file of the library compiles
// to the same bytes in any copy of the lab, and ccache shares it between copies: a grader's
// lanes, a class's build, a student's clone (tools/ccache.cmake).
std::string explore_page_dir();   // tools/explore: the explorer's page
std::string three_js_path();      // Debian's three.min.js
std::string shared_assets_dir();  // ../shared/assets: the meshes a scene may name

// The folder of this program's scene files (chapters/chNN_*/). Each chapter program defines
// it in a file of its own that CMake writes (chapters/CMakeLists.txt), for the same reason.
std::string chapter_dir();

}  // namespace rt
