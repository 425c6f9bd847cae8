// rtlab-book: builds book/*.md into HTML with pandoc, pulling code excerpts from the sources.
//
// A line of the form
//   <!-- excerpt: solutions/ch02_spheres.cpp#stable -->
// is replaced by the lines between "// @book stable" and "// @book-end" in that file (marker
// lines of exercises and other excerpts dropped), as a C++ code block. So the book shows the
// code as it is, and cannot drift from it: with --check, any excerpt whose file or marker is
// missing is reported and the exit code is 1.
//
// A line <!-- include: book/measured/FILE.md --> is replaced by that file's text: the tables
// a benchmark command writes (./lab bench complexity, ./lab bench embree), so the book shows
// what was last measured. Pictures under book/measured/ are copied like the renders.
//
// Two editions come from the same source. The instructor edition shows every excerpt
// whole. The student edition replaces the body of every exercise region (between
// "// @exercise" and "// @end") with one comment line, so it shows each exercise's
// signature and contract, never the reference answer.
//
// Each page gets links to the contents and to the previous and next chapters, every "§N.M"
// in the text becomes a link to that section (a "course §9.x" stays text), and the images
// a page shows are copied into OUT_DIR/img, so the book still works when moved.
//
//   rtlab-book --root SRC_DIR --out OUT_DIR [--edition student|instructor] [--markdown-only] [--check]
#include <algorithm>
#include <cstdlib>
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

std::vector<std::string> read_lines(const fs::path& p, bool& ok) {
    std::ifstream in(p);
    ok = bool(in);
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    return lines;
}

// The excerpt, or an error message.
bool excerpt(const fs::path& root, const std::string& file, const std::string& name, bool student, std::string& out) {
    bool ok = false;
    const auto lines = read_lines(root / file, ok);
    if (!ok) {
        out = "no such file " + file;
        return false;
    }
    static const std::regex marker(R"(^\s*// @(book|book-end|exercise|end)\b.*$)");
    const std::regex open("^\\s*// @book\\s+" + name + "\\s*$");
    static const std::regex exercise_open(R"(^(\s*)// @exercise\s+(\S+).*$)");
    static const std::regex exercise_close(R"(^\s*// @end\s*$)");
    std::vector<std::string> body;
    bool inside = false, found = false, in_exercise = false;
    for (const auto& l : lines) {
        if (!inside && std::regex_match(l, open)) {
            inside = found = true;
            continue;
        }
        if (inside && std::regex_match(l, std::regex(R"(^\s*// @book-end\s*$)"))) {
            inside = false;
            break;
        }
        if (!inside) continue;
        std::smatch m;
        if (std::regex_match(l, m, exercise_open)) {
            in_exercise = true;
            if (student)
                body.push_back(m[1].str() + "// exercise " + m[2].str() +
                               ": yours to write (book edition for students)");
            continue;
        }
        if (std::regex_match(l, exercise_close)) {
            in_exercise = false;
            continue;
        }
        if (student && in_exercise) continue;
        if (!std::regex_match(l, marker)) body.push_back(l);
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

// "## 2.4 Hitting a sphere" -> section "2.4" (chapters 0-99 and appendix letters).
const std::regex kNumberedHeading(R"(^(#{1,4})\s+(\d+\.\d+|[A-Z]\.\d+)\s+(.*?)\s*$)");

std::string section_id(const std::string& number) {
    std::string id = "sec-" + number;
    std::replace(id.begin(), id.end(), '.', '-');
    return id;
}

std::string html_name(const fs::path& md) {
    return fs::path(md).replace_extension(".html").filename().string();
}

// Links "§N.M" (not "course §9.x") to its section, outside code.
std::string link_sections(const std::string& line, const std::map<std::string, std::string>& where) {
    static const std::regex ref(R"(§(\d+\.\d+|[A-Z]\.\d+))");
    std::string out;
    bool code = false;
    std::size_t i = 0;
    while (i < line.size()) {
        if (line[i] == '`') {
            code = !code;
            out += line[i++];
            continue;
        }
        std::smatch m;
        const std::string rest = line.substr(i);
        if (!code && rest.rfind("§", 0) == 0 && std::regex_search(rest, m, ref) && m.position(0) == 0) {
            const bool course = out.size() >= 7 && out.compare(out.size() - 7, 7, "course ") == 0;
            const auto it = where.find(m[1].str());
            if (!course && it != where.end()) {
                out += "[" + m[0].str() + "](" + it->second + "#" + section_id(m[1].str()) + ")";
                i += m[0].length();
                continue;
            }
        }
        out += line[i++];
    }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    fs::path root = ".", out = "out/book";
    bool check = false, markdown_only = false, student = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--check")
            check = true;
        else if (a == "--markdown-only")
            markdown_only = true;
        else if (a == "--root" && i + 1 < argc)
            root = argv[++i];
        else if (a == "--out" && i + 1 < argc)
            out = argv[++i];
        else if (a == "--edition" && i + 1 < argc &&
                 (std::string(argv[i + 1]) == "student" || std::string(argv[i + 1]) == "instructor"))
            student = std::string(argv[++i]) == "student";
        else {
            std::cerr << "usage: rtlab-book --root SRC_DIR --out OUT_DIR [--edition student|instructor] "
                         "[--markdown-only] [--check]\n";
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
    // The reading order: the contents first, then the chapters, then the appendices.
    std::stable_partition(chapters.begin(), chapters.end(),
                          [](const fs::path& p) { return p.filename() == "index.md"; });

    // Where each numbered section is, for the links, and each page's title, for the
    // previous and next links.
    std::map<std::string, std::string> where, title;
    for (const fs::path& ch : chapters) {
        bool ok = false;
        for (const auto& l : read_lines(ch, ok)) {
            std::smatch m;
            if (std::regex_match(l, m, kNumberedHeading)) where.emplace(m[2].str(), html_name(ch));
            static const std::regex heading(R"re(^(# |title: )"?(.*?)"?\s*$)re");
            if (!title.count(html_name(ch)) && std::regex_match(l, m, heading)) title[html_name(ch)] = m[2].str();
        }
    }
    auto name = [&](const fs::path& ch) {
        const auto it = title.find(html_name(ch));
        return it == title.end() ? html_name(ch) : it->second;
    };

    static const std::regex directive(R"(^\s*<!--\s*excerpt:\s*([^#\s]+)#(\S+)\s*-->\s*$)");
    static const std::regex include(R"(^\s*<!--\s*include:\s*(\S+)\s*-->\s*$)");
    static const std::regex image(R"(\]\((\.\./)?((ch\d\d|measured)/[^)\s]+\.(png|svg))\))");
    int errors = 0;
    std::vector<std::pair<fs::path, std::string>> expanded;
    std::vector<std::string> images;
    for (std::size_t k = 0; k < chapters.size(); ++k) {
        const fs::path& ch = chapters[k];
        bool ok = false;
        const auto lines = read_lines(ch, ok);
        std::ostringstream text;
        std::string nav;
        if (ch.filename() != "index.md") {
            nav = "[Contents](index.html)";
            if (k > 1) nav += " · [← " + name(chapters[k - 1]) + "](" + html_name(chapters[k - 1]) + ")";
            if (k + 1 < chapters.size())
                nav += " · [" + name(chapters[k + 1]) + " →](" + html_name(chapters[k + 1]) + ")";
            nav = "<div class=\"nav\">\n" + nav + "\n</div>\n";
        }
        int number = 0;
        bool fence = false, front_matter = false;
        for (const auto& l : lines) {
            ++number;
            if (number == 1 && l == "---")
                front_matter = true;
            else if (front_matter && l == "---") {
                front_matter = false;
                text << l << '\n' << '\n' << nav << '\n';
                continue;
            }
            if (number == 1 && !front_matter) text << nav << '\n';
            std::smatch m;
            if (l.rfind("```", 0) == 0) fence = !fence;
            if (std::regex_match(l, m, include)) {
                bool found = false;
                const auto included = read_lines(root / m[1].str(), found);
                if (!found) {
                    std::cerr << "book/" << ch.filename().string() << ":" << number << ": no file " << m[1].str()
                              << '\n';
                    ++errors;
                }
                for (const auto& i : included) text << link_sections(i, where) << '\n';
            } else if (std::regex_match(l, m, directive)) {
                std::string code;
                if (!excerpt(root, m[1].str(), m[2].str(), student, code)) {
                    std::cerr << "book/" << ch.filename().string() << ":" << number << ": " << code << '\n';
                    ++errors;
                }
                text << code << '\n';
            } else if (!fence && !front_matter && std::regex_match(l, m, kNumberedHeading)) {
                text << l << " {#" << section_id(m[2].str()) << "}\n";
            } else if (!fence && !front_matter) {
                std::string line = link_sections(l, where);
                // Images of the renders: copied beside the book, linked there.
                std::string rewritten;
                auto begin = line.cbegin();
                for (std::sregex_iterator it(line.begin(), line.end(), image), end; it != end; ++it) {
                    rewritten.append(begin, line.cbegin() + it->position(0));
                    rewritten += "](img/" + (*it)[2].str() + ")";
                    images.push_back((*it)[2].str());
                    begin = line.cbegin() + it->position(0) + it->length(0);
                }
                rewritten.append(begin, line.cend());
                text << rewritten << '\n';
            } else {
                text << l << '\n';
            }
        }
        if (!nav.empty()) text << '\n' << nav;
        expanded.emplace_back(ch, text.str());
    }
    if (errors || check) return errors ? 1 : 0;

    fs::create_directories(out / "md");
    for (const auto& [ch, text] : expanded) std::ofstream(out / "md" / ch.filename()) << text;
    if (markdown_only) return 0;

    fs::copy_file(book / "book.css", out / "book.css", fs::copy_options::overwrite_existing);
    // A render from `./lab run` (out/chNN/) if there is one, else the golden image.
    for (const std::string& img : images) {
        const fs::path rendered = out.parent_path() / img, golden = root / "tests/golden" / img;
        const fs::path from = img.rfind("measured/", 0) == 0 ? root / "book" / img
                              : fs::exists(rendered)         ? rendered
                                                             : golden;
        if (!fs::exists(from)) {
            std::cerr << "rtlab-book: warning: no image " << img << " (run ./lab run first)\n";
            continue;
        }
        fs::create_directories((out / "img" / img).parent_path());
        fs::copy_file(from, out / "img" / img, fs::copy_options::overwrite_existing);
    }
    for (const auto& [ch, text] : expanded) {
        const fs::path md = out / "md" / ch.filename();
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
