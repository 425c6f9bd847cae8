// Chapter 16: depth of field. Its scenes are scene files (scenes/*.json) whose camera has a
// thin lens: an aperture, a focus distance and a square or round lens.
#include "app/app.hpp"

using namespace rt;

int main(int argc, char** argv) {
    ChapterApp app("ch16", "Depth of field");
    app.add_scene_files(chapter_dir(), {"row", "lights"});
    return app.run(argc, argv);
}
