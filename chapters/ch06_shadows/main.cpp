// Chapter 06: shadows. A scene file per picture, and the acne stress scene of book §6.4,
// which is built here because it takes a scale.
#include "app/app.hpp"
#include "render/acne.hpp"

using namespace rt;

int main(int argc, char** argv) {
    ChapterApp app("ch06", "Shadows");
    app.add_scene_files(chapter_dir(), {"shadows", "conic"});
    app.add_scene("acne", "the acne stress scene at 10^5 units from the origin, robust offset",
                  [] { return acne_scene(Real(1e5), Offset{OffsetMethod::robust}); });
    return app.run(argc, argv);
}
