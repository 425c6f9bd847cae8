// Chapter 05: the ray tracing program. Its scenes are scene files (scenes/*.json): the same
// format every chapter accepts with --scene FILE.json.
#include "app/app.hpp"

using namespace rt;

int main(int argc, char** argv) {
    ChapterApp app("ch05", "The ray tracing program");
    app.add_scene_files(chapter_dir(), {"spheres", "lambert", "meshes", "skipping"});
    return app.run(argc, argv);
}
