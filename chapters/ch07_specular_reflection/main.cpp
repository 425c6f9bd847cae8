// Chapter 07: specular reflection. Its scenes are scene files (scenes/*.json).
#include "app/app.hpp"

using namespace rt;

int main(int argc, char** argv) {
    ChapterApp app("ch07", "Specular reflection");
    const std::string dir = std::string(RTLAB_CHAPTER_DIR) + "/scenes/";
    for (const char* name : {"mirrors", "tinted-sphere"}) app.add_scene_file(name, dir + name + ".json");
    return app.run(argc, argv);
}
