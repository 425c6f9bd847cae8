// Chapter 18: motion blur. Its scenes are scene files (scenes/*.json) with spheres that move
// ("moves_to") and a camera shutter interval.
#include "app/app.hpp"

using namespace rt;

int main(int argc, char** argv) {
    ChapterApp app("ch18", "Motion blur");
    app.add_scene_files(chapter_dir(), {"balls", "shutter"});
    return app.run(argc, argv);
}
