// Chapter 15: soft shadows. Its scenes are scene files (scenes/*.json) lit by parallelogram
// lights; each pixel sample takes one shadow ray to one place on each light.
#include "app/app.hpp"

using namespace rt;

int main(int argc, char** argv) {
    ChapterApp app("ch15", "Soft shadows");
    app.add_scene_files(chapter_dir(), {"penumbra", "fence"});
    return app.run(argc, argv);
}
