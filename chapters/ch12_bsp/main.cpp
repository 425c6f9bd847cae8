// Chapter 12: the binary space partitioning tree. Its scenes are scene files (scenes/*.json)
// that ask for a BSP tree ("accel": "bsp" or "bsp-midpoint"); --accel picks another structure.
#include "app/app.hpp"

using namespace rt;

int main(int argc, char** argv) {
    ChapterApp app("ch12", "The BSP tree");
    app.add_scene_files(chapter_dir(), {"city", "sticks", "stadium"});
    return app.run(argc, argv);
}
