// Chapter 17: glossy reflection. Its scenes are scene files (scenes/*.json) with mirrors
// that have a glossy width.
#include "app/app.hpp"

using namespace rt;

int main(int argc, char** argv) {
    ChapterApp app("ch17", "Glossy reflection");
    app.add_scene_files(chapter_dir(), {"plates", "grazing"});
    return app.run(argc, argv);
}
