// Chapter 09: instancing. Its scenes are scene files (scenes/*.json).
#include "app/app.hpp"

using namespace rt;

int main(int argc, char** argv) {
    ChapterApp app("ch09", "Instancing");
    app.add_scene_files(chapter_dir(), {"ellipsoid", "instances"});
    return app.run(argc, argv);
}
