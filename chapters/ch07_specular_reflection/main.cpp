// Chapter 07: specular reflection. Its scenes are scene files (scenes/*.json).
#include "app/app.hpp"

using namespace rt;

int main(int argc, char** argv) {
    ChapterApp app("ch07", "Specular reflection");
    app.add_scene_files(chapter_dir(), {"mirrors", "tinted-sphere"});
    return app.run(argc, argv);
}
