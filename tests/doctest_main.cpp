// The main() of every unit-test program: doctest's, plus two things a student needs to
// read a failure: which exercises this build takes from solutions/, and, when a test stops
// at an exercise of an earlier chapter, which one and how to get past it.
#define DOCTEST_CONFIG_IMPLEMENT
#include "core/build_info.hpp"
#include "core/exercise.hpp"

#include <doctest/doctest.h>

#include <cstdio>
#include <regex>
#include <string>

namespace {

std::string this_chapter;  // "02" for test_ch02, empty for test_common

}  // namespace

REGISTER_EXCEPTION_TRANSLATOR(const rt::NotImplemented& e) {
    // The stub's message starts "exercise N.M (name) is not done yet"; chapter N is the
    // exercise's own.
    static const std::regex form(R"(^exercise (\d+)\.(\S+) \((.*)\) is not done yet)");
    const std::string what = e.what();
    std::smatch m;
    if (std::regex_search(what, m, form)) {
        std::string chapter = m[1].str();
        if (chapter.size() == 1) chapter = "0" + chapter;
        if (chapter != this_chapter)
            return doctest::String(("needs exercise " + m[1].str() + "." + m[2].str() + " (" + m[3].str() +
                                    ", chapter " + chapter + "): solve it, or take chapter " + chapter +
                                    " from solutions/ with -DRTLAB_SOLVED=\"" + chapter + "\"")
                                       .c_str());
    }
    return doctest::String(what.c_str());
}

int main(int argc, char** argv) {
    static const std::regex name(R"(test_ch(\d\d)$)");
    std::smatch m;
    const std::string program = argv[0];
    if (std::regex_search(program, m, name)) this_chapter = m[1].str();
    if (std::string(rt::build_info::track) == "exercises")
        std::printf("[rtlab] exercises track: chapters from solutions/: %s\n", rt::build_info::from_solutions);
    doctest::Context context(argc, argv);
    return context.run();
}
