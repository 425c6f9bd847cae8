// libFuzzer target: a chapter program's command line. The input is the arguments, separated
// by NUL bytes. Parsing must end in an exit code or in a checked invocation, never touch a
// file, and never accept what the renderer would refuse.
#include "app/app.hpp"
#include "fuzz_support.hpp"
#include "io/image_file.hpp"

#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const rt::ChapterApp app = [] {
        rt::ChapterApp a("chfz", "command-line fuzzing");
        a.add_scene("one", "a scene", [] { return rt::Scene{}; });
        a.add_scene("two", "another", [] { return rt::Scene{}; });
        return a;
    }();
    std::vector<std::string> args{"chfz"};
    std::string arg;
    for (std::size_t i = 0; i < size && args.size() < 32; ++i) {
        if (data[i] == 0) {
            args.push_back(arg);
            arg.clear();
        } else {
            arg += char(data[i]);
        }
    }
    args.push_back(arg);
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    rt::ChapterApp::Invocation invocation;
    const auto code = app.parse(int(argv.size()), argv.data(), invocation);
    if (code) {
        rt::fuzz::check(*code == 0 || *code == 2, "exit code other than 0 or 2");
        return 0;
    }
    try {
        rt::check_budget(invocation.options);
    } catch (const std::exception&) {
        rt::fuzz::check(false, "parse accepted options the renderer refuses");
    }
    rt::fuzz::check(rt::is_image_path(invocation.output), "parse accepted an output that is not an image path");
    return 0;
}
