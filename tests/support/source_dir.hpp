#pragma once
#include <string>

namespace rt::test {

// The lab's checkout (the top-level directory), without a trailing slash.
std::string source_dir();

}  // namespace rt::test
