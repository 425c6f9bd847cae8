// rtlab-genex: writes the student copies in exercises/ from the reference files in
// solutions/, replacing the body of every marked region with a stub that throws.
//
//   // @exercise 2.2 | sphere_roots | book §2.3
//   ...reference code...
//   // @end
//
// becomes the same two marker lines around
//   throw NotImplemented("exercise 2.2 (sphere_roots) is not done yet: see book §2.3");
// with, just above the first marker, RT_STUDENT_EXERCISE(2, 2): the student's copy records
// that it ran, so the grader can name it when a test through it fails (core/exercise.hpp).
// The book's excerpt markers ("// @book NAME", "// @book-end") are left out of the copies.
// Each student copy also gets one region of its own, "// @helpers" ... "// @end", before
// `namespace rt {`: the student's #includes and helper functions, kept like any body.
//
// A student's work is never lost. The generator owns everything outside the regions; the
// bodies inside belong to whoever wrote them:
// - Regenerating keeps every body that differs from its stub, by exercise number, and
//   writes the generator's text around it.
// - If the text outside the regions changed (an instructor's update, or a student's edit
//   there), the old file is first copied to FILE.orig.
// - If a body a student wrote has no region left to go to (the exercise was renumbered or
//   removed), nothing is written: the file is named and the exit code is 3, unless --force,
//   which writes FILE.orig first.
// With --check nothing is written: the exit code is 1 if the text outside the regions of
// any committed copy differs from what the generator makes (bodies are not compared).
// With --written nothing is written either: each copy with bodies that are not their stubs
// is listed as "FILE: 2.1 2.2" (tools/grade warns when such a chapter is graded from solutions/).
// --transplant is the class grader's (tools/grading/submission.py): the student copy of one
// solution file with the bodies and helpers of a student's file put in, and nothing else of
// theirs; OUT_FILE is written only when the student's file parses (else exit 2, one line).
//
//   rtlab-genex SOLUTIONS_DIR EXERCISES_DIR [--check | --written] [--force]
// --blank is the handout's (tools/handout.py): a solution file with every body replaced by its
// stub and nothing else changed (the book's excerpt markers stay): tools/blanks/ in a handout,
// which stands in for solutions/ there (./lab exercises regenerates from it, the book's
// excerpts come from it) and holds no answer.
//
//   rtlab-genex --transplant SOLUTION_FILE STUDENT_FILE OUT_FILE
//   rtlab-genex --blank SOLUTION_FILE OUT_FILE
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
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

void write_file(const fs::path& p, const std::string& text) {
    std::ofstream out(p, std::ios::binary);
    out << text;
    if (!out.flush()) throw Failure{"cannot write " + p.string()};
}

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
    return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

const std::regex kBegin(R"(^(\s*)// @exercise\s+(\S+)\s*\|\s*([^|]+?)\s*\|\s*(.+?)\s*$)");
const std::regex kEnd(R"(^\s*// @end\s*$)");
const std::regex kHelpers(R"(^\s*// @helpers\s*$)");
// The book's excerpt markers (tools/book.cpp reads them from solutions/ only): the student
// copies go without them.
const std::regex kBookMarker(R"(^\s*// @book(\s+\S+|-end)\s*$)");
const std::regex kLooksLikeMarker(R"(^\s*//\s*@\s*(exercise|helpers))");
const std::string kHelpersId = "helpers";
// A student's file the class grader takes regions from is refused past this size.
constexpr std::size_t kLargestStudentFile = 1 << 20, kLongestStudentLine = 4096;
// The helper region's text until the student writes there.
const std::string kHelpersStub =
    "// Your #includes and helper functions, if any (inside namespace rt { ... } to use the\n"
    "// library's names unqualified). ./lab exercises keeps these lines like an exercise body.\n";

// A file cut at its exercise regions: the text outside (with a placeholder line where each
// body was) and the bodies, by exercise number.
struct Parsed {
    std::string outside;
    std::vector<std::string> order;           // exercise numbers, in file order
    std::map<std::string, std::string> body;  // number -> the lines between the markers
    std::map<std::string, std::string> stub;  // number -> the line that throws, from its marker
};

Parsed parse(const std::string& name, const std::string& text) {
    Parsed p;
    std::istringstream in(text);
    std::string line, id;
    int number = 0, open_line = 0;
    bool inside = false;
    while (std::getline(in, line)) {
        ++number;
        std::smatch m;
        if (std::regex_match(line, kHelpers)) {
            if (inside || p.body.count(kHelpersId))
                throw Failure{name + ":" + std::to_string(number) + ": a second or nested @helpers region"};
            inside = true;
            open_line = number;
            id = kHelpersId;
            p.order.push_back(id);
            p.body[id];
            p.stub[id] = kHelpersStub;
            p.outside += line + "\n\x01\n";
        } else if (std::regex_match(line, m, kBegin)) {
            if (inside)
                throw Failure{name + ":" + std::to_string(number) + ": @exercise inside another (opened at line " +
                              std::to_string(open_line) + ")"};
            inside = true;
            open_line = number;
            id = m[2].str();
            if (p.body.count(id)) throw Failure{name + ":" + std::to_string(number) + ": exercise " + id + " twice"};
            p.order.push_back(id);
            p.body[id];
            p.stub[id] = m[1].str() + "throw NotImplemented(\"exercise " + id + " (" + trim(m[3].str()) +
                         ") is not done yet: see " + m[4].str() + "\");\n";
            p.outside += line + "\n\x01\n";  // where the body goes
        } else if (std::regex_match(line, kEnd)) {
            if (!inside) throw Failure{name + ":" + std::to_string(number) + ": @end without @exercise"};
            inside = false;
            p.outside += line + '\n';
        } else if (inside) {
            p.body[id] += line + '\n';
        } else if (std::regex_search(line, kLooksLikeMarker)) {
            throw Failure{name + ":" + std::to_string(number) +
                          ": malformed marker; expected \"// @exercise N | name | book §S\""};
        } else {
            p.outside += line + '\n';
        }
    }
    if (inside) throw Failure{name + ":" + std::to_string(open_line) + ": @exercise is never closed by @end"};
    return p;
}

// The student copy of a solution: its outside text and the stub bodies.
Parsed generate(const fs::path& source, const std::string& text) {
    Parsed solution = parse(source.string(), text);
    if (solution.body.count(kHelpersId))
        throw Failure{source.string() + ": @helpers is the student's; the generator adds it"};
    // The mark above each exercise's first marker, and the helper region before the
    // namespace, both in the text outside the bodies: the student's lines stay where they were.
    std::string outside;
    std::istringstream in(solution.outside);
    std::string line;
    bool helpers = false;
    while (std::getline(in, line)) {
        std::smatch m;
        if (std::regex_match(line, kBookMarker)) continue;
        if (std::regex_match(line, m, kBegin)) {
            const std::string id = m[2].str();
            const auto dot = id.find('.');
            if (dot == std::string::npos || id.find_first_not_of("0123456789.") != std::string::npos)
                throw Failure{source.string() + ": exercise '" + id + "' is not numbered N.M"};
            outside += m[1].str() + "RT_STUDENT_EXERCISE(" + id.substr(0, dot) + ", " + id.substr(dot + 1) +
                       ");  // tells the grader this ran (core/exercise.hpp)\n";
        } else if (!helpers && line == "namespace rt {") {
            outside += "// @helpers\n\x01\n// @end\n\n";
            solution.order.insert(solution.order.begin(), kHelpersId);
            solution.stub[kHelpersId] = kHelpersStub;
            helpers = true;
        }
        outside += line + '\n';
    }
    if (!helpers) throw Failure{source.string() + ": no \"namespace rt {\" line to put the helper region before"};
    solution.outside = outside;
    solution.body = solution.stub;
    solution.outside = "// STUDENT COPY of solutions/" + source.filename().string() +
                       ", made by tools/gen_exercises.cpp.\n"
                       "// Write your code between each \"@exercise\" line and its \"@end\", in place of the throw.\n"
                       "// Only those lines are yours: ./lab exercises keeps them and rewrites the rest.\n" +
                       solution.outside;
    return solution;
}

std::string assemble(const Parsed& p, const std::map<std::string, std::string>& bodies) {
    std::string out;
    std::size_t k = 0, at = 0;
    while (true) {
        const auto hole = p.outside.find("\n\x01\n", at);
        if (hole == std::string::npos) break;
        out += p.outside.substr(at, hole + 1 - at) + bodies.at(p.order[k++]);
        at = hole + 3;
    }
    return out + p.outside.substr(at);
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    auto flag = [&](const char* name) {
        const bool on = std::find(args.begin(), args.end(), name) != args.end();
        args.erase(std::remove(args.begin(), args.end(), name), args.end());
        return on;
    };
    const bool check = flag("--check"), written = flag("--written"), force = flag("--force");
    std::string only;  // --chapters "01 02": empty for every chapter
    if (const auto at = std::find(args.begin(), args.end(), "--chapters"); at != args.end()) {
        if (at + 1 == args.end()) {
            std::cerr << "rtlab-genex: --chapters needs a list, e.g. \"01 02\"\n";
            return 2;
        }
        only = " " + *(at + 1) + " ";
        args.erase(at, at + 2);
    }
    if (flag("--blank")) {
        if (args.size() != 2) {
            std::cerr << "usage: rtlab-genex --blank SOLUTION_FILE OUT_FILE\n";
            return 2;
        }
        try {
            const Parsed solution = parse(args[0], read_file(args[0]));
            write_file(args[1], assemble(solution, solution.stub));
            return 0;
        } catch (const Failure& f) {
            std::cerr << "rtlab-genex: " << f.message << '\n';
            return 2;
        }
    }
    if (flag("--transplant")) {
        if (args.size() != 3) {
            std::cerr << "usage: rtlab-genex --transplant SOLUTION_FILE STUDENT_FILE OUT_FILE\n";
            return 2;
        }
        try {
            const fs::path source(args[0]), student(args[1]), out(args[2]);
            const Parsed want = generate(source, read_file(source));
            // The student's file is anyone's: a text of a sane size, with lines the marker
            // patterns can take, before any parsing.
            const std::string name = student.filename().string();
            if (!fs::is_regular_file(fs::symlink_status(student))) throw Failure{name + " is not a plain file"};
            if (fs::file_size(student) > kLargestStudentFile) throw Failure{name + " is larger than 1 MiB"};
            const std::string text = read_file(student);
            if (text.find('\0') != std::string::npos) throw Failure{name + " is not a text file"};
            std::size_t line = 1, at = 0;
            for (std::size_t end; (end = text.find('\n', at)) != std::string::npos || at < text.size(); ++line) {
                if (end == std::string::npos) end = text.size();
                if (end - at > kLongestStudentLine)
                    throw Failure{name + ":" + std::to_string(line) + ": a line longer than 4096 characters"};
                at = end + 1;
            }
            const Parsed have = parse(student.filename().string(), text);
            std::map<std::string, std::string> bodies = want.body;
            for (const auto& [id, body] : have.body)
                if (bodies.count(id)) bodies[id] = body;
            write_file(out, assemble(want, bodies));
            return 0;
        } catch (const Failure& f) {
            std::cerr << "rtlab-genex: " << f.message << '\n';
            return 2;
        }
    }
    if (args.size() != 2) {
        std::cerr << "usage: rtlab-genex SOLUTIONS_DIR EXERCISES_DIR [--check | --written] [--force]\n";
        return 2;
    }
    const fs::path solutions(args[0]), exercises(args[1]);
    try {
        if (!fs::is_directory(solutions)) throw Failure{"not a directory: " + solutions.string()};
        std::vector<fs::path> sources;
        for (const auto& e : fs::directory_iterator(solutions)) {
            const std::string name = e.path().filename().string();
            const bool wanted =
                only.empty() || (name.size() > 4 && only.find(" " + name.substr(2, 2) + " ") != std::string::npos);
            if (e.path().extension() == ".cpp" && wanted) sources.push_back(e.path());
        }
        std::sort(sources.begin(), sources.end());
        int stale = 0, refused = 0;
        for (const fs::path& src : sources) {
            const Parsed want = generate(src, read_file(src));
            const fs::path dst = exercises / src.filename();
            if (!fs::exists(dst)) {
                if (written) continue;
                if (check) {
                    std::cerr << dst.string() << " is missing: run ./lab exercises\n";
                    ++stale;
                } else {
                    fs::create_directories(exercises);
                    write_file(dst, assemble(want, want.body));
                    std::cout << "wrote " << dst.string() << '\n';
                }
                continue;
            }
            const std::string old_text = read_file(dst);
            const Parsed have = parse(dst.string(), old_text);
            // The student's bodies: every one that is not the stub it started as.
            std::map<std::string, std::string> bodies = want.body;
            std::vector<std::string> orphans, mine;
            int kept = 0;
            for (const auto& [id, body] : have.body) {
                const auto stub = want.body.find(id);
                if (stub == want.body.end()) {
                    if (trim(body).rfind("throw NotImplemented(", 0) != 0) orphans.push_back(id);
                } else if (body != stub->second) {
                    bodies[id] = body;
                    ++kept;
                    if (id != kHelpersId) mine.push_back(id);
                }
            }
            if (written) {
                if (!mine.empty()) {
                    std::cout << dst.string() << ':';
                    for (const auto& id : mine) std::cout << ' ' << id;
                    std::cout << '\n';
                }
                continue;
            }
            const bool outside_changed = have.outside != want.outside;
            if (check) {
                if (outside_changed) {
                    std::cerr << dst.string() << " differs from what solutions/ makes outside the exercise regions"
                              << " (bodies are not compared): run ./lab exercises, which keeps your bodies\n";
                    ++stale;
                }
                continue;
            }
            if (!orphans.empty() && !force) {
                std::cerr << dst.string() << ": your body of exercise";
                for (const auto& id : orphans) std::cerr << ' ' << id;
                std::cerr << " has no exercise region left in " << src.string()
                          << "; nothing written (move the code, or use --force, which saves the file as "
                          << dst.string() << ".orig first)\n";
                ++refused;
                continue;
            }
            const std::string text = assemble(want, bodies);
            if (text == old_text) continue;
            if (outside_changed || !orphans.empty()) {
                write_file(dst.string() + ".orig", old_text);
                std::cout << "saved " << dst.string() << ".orig\n";
            }
            write_file(dst, text);
            std::cout << "wrote " << dst.string() << " (kept " << kept << " exercise bodies written there)\n";
        }
        if (written) return 0;
        if (fs::is_directory(exercises))
            for (const auto& e : fs::directory_iterator(exercises))
                if (e.path().extension() == ".cpp" && !fs::exists(solutions / e.path().filename())) {
                    std::cerr << e.path().string() << " has no counterpart in " << solutions.string() << '\n';
                    ++stale;
                }
        if (refused) return 3;
        return stale ? 1 : 0;
    } catch (const Failure& f) {
        std::cerr << "rtlab-genex: " << f.message << '\n';
        return 2;
    }
}
