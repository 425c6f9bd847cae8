#pragma once
// What the distribution chapters' tests share (tests/test_ch15.cpp ... test_ch18.cpp): a scene
// written inline as scene-file text, and the options of a small jittered render.
#include "io/scene_file.hpp"
#include "render/render.hpp"

#include <string>

namespace rt::test {

// The scene of a scene file's text, with its search structure built.
inline Scene scene_text(const std::string& text, AccelKind accel = AccelKind::fast) {
    Scene scene = load_scene_text(text, "test.json", ".");
    scene.build_accel(accel);
    return scene;
}

// width x height pixels, spp jittered samples each (a square number), box filter, 2 threads.
inline RenderOptions jittered(int width, int height, int spp) {
    RenderOptions o;
    o.width = width;
    o.height = height;
    o.spp = spp;
    o.threads = 2;
    o.antialiasing = {PixelPattern::jittered, PixelFilter::box};
    return o;
}

}  // namespace rt::test
