#pragma once
// What a program was linked with: the lab's version (CMake's project version, stated only
// there), the track, and which chapters' exercises come from
// solutions/. Defined in a small object the build generates for each program (see the
// top-level CMakeLists.txt, rtlab_link_exercises), so changing RTLAB_SOLVED relinks
// programs and recompiles nothing of the library.
namespace rt::build_info {
extern const char* const version;         // "0.1.0"
extern const char* const track;           // "solutions" or "exercises"
extern const char* const from_solutions;  // e.g. "all", "none", "01 02", "01, and 06-18 (after ch05)"
extern const char* const solved;          // RTLAB_SOLVED as given, e.g. "01;02" (exercises track)
}  // namespace rt::build_info
