// Chapter 09: instancing. Its scenes are scene files (scenes/*.json).
#include "app/app.hpp"

using namespace rt;

int main(int argc, char** argv) {
    ChapterApp app("ch09", "Instancing");
    const std::string dir = std::string(RTLAB_CHAPTER_DIR) + "/scenes/";
    for (const char* name : {"ellipsoid", "instances"}) app.add_scene_file(name, dir + name + ".json");
    return app.run(argc, argv);
}
