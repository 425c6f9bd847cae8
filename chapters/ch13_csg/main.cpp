// Chapter 13: constructive solid geometry. Its scenes are scene files (scenes/*.json) whose
// "csg" surfaces combine closed solids by union, intersection and difference.
#include "app/app.hpp"

using namespace rt;

int main(int argc, char** argv) {
    ChapterApp app("ch13", "Constructive solid geometry");
    app.add_scene_files(chapter_dir(), {"lens", "die", "nested", "meshes", "coplanar"});
    return app.run(argc, argv);
}
