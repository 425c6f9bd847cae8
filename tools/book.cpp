// rtlab-book: builds book/*.md into HTML with pandoc, pulling code excerpts from the sources.
//
// A line of the form
//   <!-- excerpt: solutions/ch02_spheres.cpp#stable -->
// is replaced by the lines between "// @book stable" and "// @book-end" in that file (marker
// lines of exercises and other excerpts dropped), as a C++ code block. So the book shows the
// code as it is, and cannot drift from it: with --check, any excerpt whose file or marker is
// missing is reported and the exit code is 1.
//
//   rtlab-book --root SRC_DIR --out OUT_DIR [--check]
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

std::vector<std::string> read_lines(const fs::path& p, bool& ok) {
    std::ifstream in(p);
    ok = bool(in);
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    return lines;
}

// The excerpt, or an error message.
bool excerpt(const fs::path& root, const std::string& file, const std::string& name, std::string& out) {
    bool ok = false;
    const auto lines = read_lines(root / file, ok);
    if (!ok) {
        out = "no such file " + file;
        return false;
    }
    static const std::regex marker(R"(^\s*// @(book|book-end|exercise|end)\b.*$)");
    const std::regex open("^\\s*// @book\\s+" + name + "\\s*$");
    std::vector<std::string> body;
    bool inside = false, found = false;
    for (const auto& l : lines) {
        if (!inside && std::regex_match(l, open)) {
            inside = found = true;
            continue;
        }
        if (inside && std::regex_match(l, std::regex(R"(^\s*// @book-end\s*$)"))) {
            inside = false;
            break;
        }
        if (inside && !std::regex_match(l, marker)) body.push_back(l);
    }
    if (!found || inside) {
        out = found ? "marker '" + name + "' in " + file + " has no @book-end"
                    : "no marker '// @book " + name + "' in " + file;
        return false;
    }
    std::size_t indent = std::string::npos;
    for (const auto& l : body)
        if (l.find_first_not_of(' ') != std::string::npos) indent = std::min(indent, l.find_first_not_of(' '));
    std::ostringstream s;
    s << "```cpp\n";
    for (const auto& l : body) s << (l.size() > indent ? l.substr(indent) : std::string()) << '\n';
    s << "```\n\n<p class=\"source\">from <code>" << file << "</code></p>";
    out = s.str();
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    fs::path root = ".", out = "out/book";
    bool check = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--check")
            check = true;
        else if (a == "--root" && i + 1 < argc)
            root = argv[++i];
        else if (a == "--out" && i + 1 < argc)
            out = argv[++i];
        else {
            std::cerr << "usage: rtlab-book --root SRC_DIR --out OUT_DIR [--check]\n";
            return 2;
        }
    }
    const fs::path book = root / "book";
    std::vector<fs::path> chapters;
    if (fs::is_directory(book))
        for (const auto& e : fs::directory_iterator(book))
            if (e.path().extension() == ".md") chapters.push_back(e.path());
    std::sort(chapters.begin(), chapters.end());
    if (chapters.empty()) {
        std::cerr << "rtlab-book: no chapters in " << book.string() << '\n';
        return 2;
    }

    static const std::regex directive(R"(^\s*<!--\s*excerpt:\s*([^#\s]+)#(\S+)\s*-->\s*$)");
    int errors = 0;
    std::vector<std::pair<fs::path, std::string>> expanded;
    for (const fs::path& ch : chapters) {
        bool ok = false;
        const auto lines = read_lines(ch, ok);
        std::ostringstream text;
        int number = 0;
        for (const auto& l : lines) {
            ++number;
            std::smatch m;
            if (std::regex_match(l, m, directive)) {
                std::string code;
                if (!excerpt(root, m[1].str(), m[2].str(), code)) {
                    std::cerr << "book/" << ch.filename().string() << ":" << number << ": " << code << '\n';
                    ++errors;
                }
                text << code << '\n';
            } else {
                text << l << '\n';
            }
        }
        expanded.emplace_back(ch, text.str());
    }
    if (errors || check) return errors ? 1 : 0;

    fs::create_directories(out / "md");
    fs::copy_file(book / "book.css", out / "book.css", fs::copy_options::overwrite_existing);
    for (const auto& [ch, text] : expanded) {
        const fs::path md = out / "md" / ch.filename();
        std::ofstream(md) << text;
        const fs::path html = out / ch.filename().replace_extension(".html");
        const std::string cmd =
            "pandoc --standalone --mathml --toc --toc-depth=2 --css book.css --resource-path=" + out.string() +
            " -o '" + html.string() + "' '" + md.string() + "'";
        if (std::system(cmd.c_str()) != 0) {
            std::cerr << "rtlab-book: pandoc failed on " << ch.string() << '\n';
            return 1;
        }
        std::cout << "wrote " << html.string() << '\n';
    }
    return 0;
}
