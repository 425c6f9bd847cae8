// Chapter 05: the ray tracing program. Its scenes are scene files (scenes/*.json): the same
// format every chapter accepts with --scene FILE.json.
#include "app/app.hpp"

using namespace rt;

int main(int argc, char** argv) {
    ChapterApp app("ch05", "The ray tracing program");
    const std::string dir = std::string(RTLAB_CHAPTER_DIR) + "/scenes/";
    for (const char* name : {"spheres", "lambert", "meshes", "skipping"})
        app.add_scene_file(name, dir + name + ".json");
    return app.run(argc, argv);
}
