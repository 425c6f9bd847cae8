// The checkout the tests read their data from. Only this file knows the absolute path, so
// the test sources compile the same in any copy of the lab (and ccache can share them).
#include "support/source_dir.hpp"

namespace rt::test {

std::string source_dir() {
    return RTLAB_SOURCE_DIR;
}

}  // namespace rt::test
