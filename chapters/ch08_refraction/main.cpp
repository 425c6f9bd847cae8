// Chapter 08: refraction. Its scenes are scene files (scenes/*.json).
#include "app/app.hpp"

using namespace rt;

int main(int argc, char** argv) {
    ChapterApp app("ch08", "Refraction");
    const std::string dir = std::string(RTLAB_CHAPTER_DIR) + "/scenes/";
    for (const char* name : {"glass-sphere", "glass-block", "tir"}) app.add_scene_file(name, dir + name + ".json");
    return app.run(argc, argv);
}
