// Chapter 10: bounding boxes and the BVH. Its scenes are scene files (scenes/*.json), each
// naming the structure it is searched with ("accel"); --accel picks another.
#include "app/app.hpp"

using namespace rt;

int main(int argc, char** argv) {
    ChapterApp app("ch10", "Bounding boxes and the bounding volume hierarchy");
    app.add_scene_files(chapter_dir(), {"spheres", "terrain", "soup", "cost"});
    return app.run(argc, argv);
}
