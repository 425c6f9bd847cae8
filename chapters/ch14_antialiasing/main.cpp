// Chapter 14: antialiasing. Its scenes are scene files (scenes/*.json) that ask for a pattern
// of pixel samples and a filter ("antialiasing"); --pattern, --filter and --spp override them.
#include "app/app.hpp"

using namespace rt;

int main(int argc, char** argv) {
    ChapterApp app("ch14", "Antialiasing");
    app.add_scene_files(chapter_dir(), {"checker", "edges"});
    return app.run(argc, argv);
}
