// Chapter 11: the uniform grid. Its scenes are scene files (scenes/*.json) that ask for the
// grid ("accel": "grid"); --accel picks another structure.
#include "app/app.hpp"

using namespace rt;

int main(int argc, char** argv) {
    ChapterApp app("ch11", "The uniform grid");
    app.add_scene_files(chapter_dir(), {"atoms", "terrain", "stadium"});
    return app.run(argc, argv);
}
