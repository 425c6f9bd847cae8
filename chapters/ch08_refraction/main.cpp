// Chapter 08: refraction. Its scenes are scene files (scenes/*.json).
#include "app/app.hpp"

using namespace rt;

int main(int argc, char** argv) {
    ChapterApp app("ch08", "Refraction");
    app.add_scene_files(chapter_dir(), {"glass-sphere", "glass-block", "tir"});
    return app.run(argc, argv);
}
