#pragma once
// The lab explorer (chNN --explore, ./lab explore): a page served on 127.0.0.1 that shows the
// chapter's scene rendered progressively, moves its camera with the mouse, and shows what any
// clicked pixel sees and the ray tree behind it (book §0, "The lab explorer").
#include "app/app.hpp"

namespace rt {

// Serves until the process is interrupted. Exit code 2 (one line on stderr) when the scene
// cannot be loaded or the port cannot be had.
int explore(const ChapterApp& app, const ChapterApp::Invocation& invocation);

}  // namespace rt
