// The one file of the library compiled with absolute paths (see lab_paths.hpp).
#include "app/lab_paths.hpp"

namespace rt {

std::string explore_page_dir() {
    return RTLAB_EXPLORE_DIR;
}

std::string three_js_path() {
    return RTLAB_THREE_JS;
}

std::string shared_assets_dir() {
    return RTLAB_SHARED_ASSETS;
}

}  // namespace rt
