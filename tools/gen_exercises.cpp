// rtlab-genex: writes the student copies in exercises/ from the reference files in
// solutions/, replacing the body of every marked region with a stub that throws.
//
//   // @exercise 2.2 | sphere_roots | book §2.3
//   ...reference code...
//   // @end
//
// becomes the same two marker lines around
//   throw NotImplemented("exercise 2.2 (sphere_roots) is not done yet: see book §2.3");
//
// With --check nothing is written; the exit code is 1 if any committed copy differs.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Failure {
    std::string message;
};

std::string read_file(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    if (!in) throw Failure{"cannot read " + p.string()};
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
    return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

std::string generate(const fs::path& source, const std::string& text) {
    static const std::regex begin(R"(^(\s*)// @exercise\s+(\S+)\s*\|\s*([^|]+?)\s*\|\s*(.+?)\s*$)");
    static const std::regex end(R"(^\s*// @end\s*$)");
    std::istringstream in(text);
    std::ostringstream out;
    out << "// STUDENT COPY of solutions/" << source.filename().string() << ", made by tools/gen_exercises.cpp.\n"
        << "// Write your code between each \"@exercise\" line and its \"@end\", in place of the throw.\n";
    std::string line;
    int number = 0, open_line = 0;
    bool inside = false;
    while (std::getline(in, line)) {
        ++number;
        std::smatch m;
        if (std::regex_match(line, m, begin)) {
            if (inside)
                throw Failure{source.string() + ":" + std::to_string(number) +
                              ": @exercise inside another (opened at line " + std::to_string(open_line) + ")"};
            inside = true;
            open_line = number;
            out << line << '\n'
                << m[1].str() << "throw NotImplemented(\"exercise " << m[2].str() << " (" << trim(m[3].str())
                << ") is not done yet: see " << m[4].str() << "\");\n";
        } else if (std::regex_match(line, end)) {
            if (!inside) throw Failure{source.string() + ":" + std::to_string(number) + ": @end without @exercise"};
            inside = false;
            out << line << '\n';
        } else if (line.find("@exercise") != std::string::npos && !inside) {
            throw Failure{source.string() + ":" + std::to_string(number) +
                          ": malformed marker; expected \"// @exercise N | name | book §S\""};
        } else if (!inside) {
            out << line << '\n';
        }
    }
    if (inside)
        throw Failure{source.string() + ":" + std::to_string(open_line) + ": @exercise is never closed by @end"};
    return out.str();
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    const bool check = std::find(args.begin(), args.end(), "--check") != args.end();
    args.erase(std::remove(args.begin(), args.end(), "--check"), args.end());
    if (args.size() != 2) {
        std::cerr << "usage: rtlab-genex SOLUTIONS_DIR EXERCISES_DIR [--check]\n";
        return 2;
    }
    const fs::path solutions(args[0]), exercises(args[1]);
    try {
        if (!fs::is_directory(solutions)) throw Failure{"not a directory: " + solutions.string()};
        std::vector<fs::path> sources;
        for (const auto& e : fs::directory_iterator(solutions))
            if (e.path().extension() == ".cpp") sources.push_back(e.path());
        std::sort(sources.begin(), sources.end());
        int stale = 0;
        for (const fs::path& src : sources) {
            const std::string want = generate(src, read_file(src));
            const fs::path dst = exercises / src.filename();
            const std::string have = fs::exists(dst) ? read_file(dst) : std::string();
            if (have == want) continue;
            if (check) {
                std::cerr << dst.string() << " is out of date with " << src.string() << ": run ./lab exercises\n";
                ++stale;
            } else {
                fs::create_directories(exercises);
                std::ofstream(dst, std::ios::binary) << want;
                std::cout << "wrote " << dst.string() << '\n';
            }
        }
        if (fs::is_directory(exercises))
            for (const auto& e : fs::directory_iterator(exercises))
                if (e.path().extension() == ".cpp" && !fs::exists(solutions / e.path().filename())) {
                    std::cerr << e.path().string() << " has no counterpart in " << solutions.string() << '\n';
                    ++stale;
                }
        return stale ? 1 : 0;
    } catch (const Failure& f) {
        std::cerr << "rtlab-genex: " << f.message << '\n';
        return 2;
    }
}
