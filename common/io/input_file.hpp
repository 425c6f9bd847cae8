#pragma once
// Reading a whole input file, refused early and in one line if it is not a regular file or
// is larger than its limit: a scene, a mesh or an image never costs more than its limit.
#include "core/limits.hpp"

#include <string>

namespace rt {

// `kind` names the file in messages ("scene file", "mesh"). Throws std::runtime_error:
// "KIND PATH: no such file", "...: is a directory", "...: is not a regular file",
// "...: KIND size must be in 0..N bytes, not M".
std::string read_input_file(const std::string& path, const std::string& kind, const limits::Range& size_limit);

}  // namespace rt
