// rtlab-book: builds book/*.md into HTML with pandoc, pulling code excerpts from the sources.
//
// A line of the form
//   <!-- excerpt: solutions/ch02_spheres.cpp#stable -->
// is replaced by the lines between "// @book stable" and "// @book-end" in that file (marker
// lines of exercises and other excerpts dropped), as a C++ code block. So the book shows the
// code as it is, and cannot drift from it.
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
// in the text becomes a link to that section, and the images a page shows are copied into
// OUT_DIR/img, so the book still works when moved.
//
// The build and --check fail (exit 1, one line per problem naming file and line) on what
// would break the book silently (book §B.7): an excerpt or include whose file or marker is
// missing; a heading glued to the line above it (pandoc reads it as text: no heading, no
// contents entry, no anchor); a link to a page or #anchor the book does not have; a bare
// §N.M that names no section of this book; a §N.M followed by a quoted title, as in
// §10.8 "Tests and exercises", whose section has another title; a picture with no source
// (a golden image, a chapter's scene, a figure description, book/measured/, or a line of
// book/pictures.txt). A normal build also fails on a picture that is not there to copy.
// "course §9.5" (in any case) and §N.M.K (another text's numbering) stay plain text.
//
//   rtlab-book --root SRC_DIR --out OUT_DIR [--edition student|instructor] [--markdown-only] [--check]
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <set>
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

// A students' handout (tools/handout.py) has tools/blanks/ in place of solutions/.
bool is_handout(const fs::path& root) {
    return fs::is_directory(root / "tools" / "blanks") && !fs::exists(root / "solutions");
}

// The excerpt, or an error message.
bool excerpt(const fs::path& root, const std::string& file, const std::string& name, bool student, std::string& out) {
    bool ok = false;
    // A students' handout has no solutions/: tools/blanks/ holds the same files with every body
    // a stub (tools/handout.py), which the student edition shows the same way.
    fs::path path = root / file;
    if (file.rfind("solutions/", 0) == 0 && is_handout(root))
        path = root / "tools" / "blanks" / file.substr(std::string("solutions/").size());
    const auto lines = read_lines(path, ok);
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

// The identifier pandoc gives a heading without one of its own: letters, digits, "_", "-"
// and "." kept, spaces as hyphens, lower case, nothing before the first letter.
std::string pandoc_id(const std::string& text) {
    std::string id;
    for (const unsigned char c : text) {
        const bool letter = std::isalpha(c) || c >= 0x80;
        if (id.empty() && !letter) continue;
        if (letter || std::isdigit(c) || c == '_' || c == '-' || c == '.')
            id += char(std::tolower(c));
        else if (c == ' ')
            id += '-';
    }
    return id.empty() ? "section" : id;
}

struct Section {
    std::string page, title;
};

bool ends_with_course(const std::string& text) {
    static const std::regex course(R"((^|\W)course\s*$)", std::regex::icase);
    return std::regex_search(text, course);
}

// Links "§N.M" to its section, outside code. Not linked: "course §9.5" in any case (also with
// "course" ending the line before: after_course), and §N.M.K, another text's numbering. A bare
// §N.M that names no section, and one followed by a quoted title that is not its section's,
// add a line to problems.
std::string link_sections(const std::string& line, const std::map<std::string, Section>& where, bool after_course,
                          std::vector<std::string>& problems) {
    static const std::regex ref(R"(^§(\d+\.\d+|[A-Z]\.\d+)(\.\d+)?)");
    static const std::regex quoted(R"re(^ (?:"([^"]+)"|“([^”]+)”))re");
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
        if (code || rest.rfind("§", 0) != 0 || !std::regex_search(rest, m, ref)) {
            out += line[i++];
            continue;
        }
        const bool course =
            ends_with_course(out) || (after_course && out.find_first_not_of(" \t") == std::string::npos);
        const auto it = where.find(m[1].str());
        if (course || m[2].matched) {
            out += m[0].str();
        } else if (it == where.end()) {
            problems.push_back(m[0].str() +
                               " names no section of this book (a section of the course is written "
                               "\"course " +
                               m[0].str() + "\")");
            out += m[0].str();
        } else {
            std::smatch q;
            const std::string after = rest.substr(m.length(0));
            if (std::regex_search(after, q, quoted)) {
                const std::string title = q[1].matched ? q[1].str() : q[2].str();
                if (title != it->second.title)
                    problems.push_back(m[0].str() + " quotes the title \"" + title + "\" but its title is \"" +
                                       it->second.title + "\"");
            }
            out += "[" + m[0].str() + "](" + it->second.page + "#" + section_id(m[1].str()) + ")";
        }
        i += m.length(0);
    }
    return out;
}

// The text outside inline code spans, for the link check.
std::string outside_code(const std::string& line) {
    std::string out;
    bool code = false;
    for (const char c : line) {
        if (c == '`')
            code = !code;
        else if (!code)
            out += c;
    }
    return out;
}

// Where a picture the book shows comes from, or "" if it has none (see the file's header).
bool has_source(const fs::path& root, const std::string& img, const std::set<std::string>& run_pictures) {
    if (img.rfind("measured/", 0) == 0) return fs::exists(root / "book" / img);
    if (fs::exists(root / "tests/golden" / img) || run_pictures.count(img)) return true;
    static const std::regex scene(R"(^(ch\d\d)/([^/]+)\.png$)");
    static const std::regex figure(R"(^ch(\d\d)/figures/([^/]+)\.svg$)");
    std::smatch m;
    if (std::regex_match(img, m, scene))
        return fs::exists(root / "tests/golden" / m[1].str() / (m[2].str() + ".mean.pfm"));
    if (std::regex_match(img, m, figure) && fs::is_directory(root / "chapters"))
        for (const auto& e : fs::directory_iterator(root / "chapters"))
            if (e.path().filename().string().rfind("ch" + m[1].str() + "_", 0) == 0 &&
                fs::exists(e.path() / "figures" / (m[2].str() + ".json")))
                return true;
    return false;
}

// The pictures `./lab run` makes beyond the chapters' scenes: book/pictures.txt, "STEP PICTURE"
// per line, which ./lab reads too.
std::set<std::string> read_run_pictures(const fs::path& root) {
    bool ok = false;
    std::set<std::string> pictures;
    for (const auto& l : read_lines(root / "book/pictures.txt", ok)) {
        std::istringstream words(l);
        std::string step, picture;
        if (l.empty() || l[0] == '#' || !(words >> step >> picture)) continue;
        pictures.insert(picture);
    }
    return pictures;
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
    if (!student && is_handout(root)) {
        std::cerr << "rtlab-book: this is a students' handout: it has the students' edition only\n";
        return 2;
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

    // Where each numbered section is and its title, for the links; each page's anchors, for
    // the link check; and each page's title, for the previous and next links.
    std::map<std::string, Section> where;
    std::map<std::string, std::string> title;
    std::map<std::string, std::set<std::string>> anchors;
    for (const fs::path& ch : chapters) {
        bool ok = false, fence = false;
        std::map<std::string, int> seen;  // pandoc numbers a repeated identifier: id, id-1, ...
        auto& ids = anchors[html_name(ch)];
        for (const auto& l : read_lines(ch, ok)) {
            if (l.rfind("```", 0) == 0) fence = !fence;
            std::smatch m;
            static const std::regex heading(R"(^#{1,6}\s+(.*?)\s*(\{#([^}\s]+)\})?\s*$)");
            if (!fence && std::regex_match(l, m, kNumberedHeading))
                where.emplace(m[2].str(), Section{html_name(ch), m[3].str()});
            if (!fence && std::regex_match(l, m, heading)) {
                std::string id = m[3].matched ? m[3].str() : pandoc_id(outside_code(m[1].str()) + "");
                if (std::smatch n; std::regex_match(l, n, kNumberedHeading)) id = section_id(n[2].str());
                const int k = seen[id]++;
                ids.insert(k ? id + "-" + std::to_string(k) : id);
            }
            static const std::regex page_title(R"re(^(# |title: )"?(.*?)"?\s*$)re");
            if (!title.count(html_name(ch)) && std::regex_match(l, m, page_title)) title[html_name(ch)] = m[2].str();
        }
    }
    auto name = [&](const fs::path& ch) {
        const auto it = title.find(html_name(ch));
        return it == title.end() ? html_name(ch) : it->second;
    };
    const std::set<std::string> run_pictures = read_run_pictures(root);

    static const std::regex directive(R"(^\s*<!--\s*excerpt:\s*([^#\s]+)#(\S+)\s*-->\s*$)");
    static const std::regex include(R"(^\s*<!--\s*include:\s*(\S+)\s*-->\s*$)");
    static const std::regex image(R"(\]\((\.\./)?((ch\d\d|measured)/[^)\s]+\.(png|svg))\))");
    static const std::regex link(R"(\]\(([^)\s]+)\))");
    static const std::regex heading_line(R"(^#{1,6}(\s|$))");
    int errors = 0;
    std::vector<std::pair<fs::path, std::string>> expanded;
    std::map<std::string, std::string> images;  // picture -> where the book first shows it
    for (std::size_t k = 0; k < chapters.size(); ++k) {
        const fs::path& ch = chapters[k];
        const std::string page = html_name(ch), file = "book/" + ch.filename().string();
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
        bool fence = false, front_matter = false, after_course = false;
        std::string previous;  // the line before, outside code and front matter
        auto problem = [&](const std::string& what) {
            std::cerr << file << ":" << number << ": " << what << '\n';
            ++errors;
        };
        auto linked = [&](const std::string& l) {
            std::vector<std::string> problems;
            std::string done = link_sections(l, where, after_course, problems);
            for (const auto& p : problems) problem(p);
            after_course = ends_with_course(outside_code(l));
            return done;
        };
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
            const bool fence_line = l.rfind("```", 0) == 0;
            if (fence_line) fence = !fence;
            if (!fence && !fence_line && !front_matter) {
                if (std::regex_search(l, heading_line) && !previous.empty() && previous != "---")
                    problem("heading glued to the line above it (pandoc reads it as text): add a blank line");
                for (std::sregex_iterator it(l.begin(), l.end(), link), end; it != end; ++it) {
                    const std::string target = (*it)[1].str();
                    const auto hash = target.find('#');
                    const std::string to = target.substr(0, hash);
                    if (target.find(':') != std::string::npos || to.find('/') != std::string::npos) continue;
                    if (!to.empty() && fs::path(to).extension() != ".html") continue;
                    const auto a = anchors.find(to.empty() ? page : to);
                    if (a == anchors.end())
                        problem("link to " + target + ": the book has no page " + to);
                    else if (hash != std::string::npos && !a->second.count(target.substr(hash + 1)))
                        problem("link to " + target + ": " + a->first + " has no anchor #" + target.substr(hash + 1));
                }
            }
            if (!front_matter && !fence_line) previous = fence ? std::string() : l;
            if (std::regex_match(l, m, include)) {
                bool found = false;
                const auto included = read_lines(root / m[1].str(), found);
                if (!found) problem("no file " + m[1].str());
                for (const auto& i : included) text << linked(i) << '\n';
            } else if (std::regex_match(l, m, directive)) {
                std::string code;
                if (!excerpt(root, m[1].str(), m[2].str(), student, code)) problem(code);
                text << code << '\n';
            } else if (!fence && !front_matter && std::regex_match(l, m, kNumberedHeading)) {
                text << l << " {#" << section_id(m[2].str()) << "}\n";
            } else if (!fence && !front_matter) {
                std::string line = linked(l);
                // Images of the renders: copied beside the book, linked there.
                std::string rewritten;
                auto begin = line.cbegin();
                for (std::sregex_iterator it(line.begin(), line.end(), image), end; it != end; ++it) {
                    rewritten.append(begin, line.cbegin() + it->position(0));
                    rewritten += "](img/" + (*it)[2].str() + ")";
                    const std::string img = (*it)[2].str();
                    images.emplace(img, file + ":" + std::to_string(number));
                    if (!has_source(root, img, run_pictures))
                        problem("picture " + img +
                                " has no source: no golden image, chapter scene, figure description "
                                "(chapters/chNN_*/figures/NAME.json), file under book/measured/ or line in "
                                "book/pictures.txt");
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

    // A render from `./lab run` (out/chNN/) if there is one, else the golden image. Every
    // missing one is named before anything is built: a book with holes is not a book.
    std::vector<std::pair<std::string, fs::path>> copies;
    for (const auto& [img, place] : images) {
        const fs::path rendered = out.parent_path() / img, golden = root / "tests/golden" / img;
        const fs::path from = img.rfind("measured/", 0) == 0 ? root / "book" / img
                              : fs::exists(rendered)         ? rendered
                                                             : golden;
        if (fs::exists(from))
            copies.emplace_back(img, from);
        else {
            std::cerr << place << ": no picture " << img << " (./lab run makes it: run it first)\n";
            ++errors;
        }
    }
    if (errors) return 1;
    fs::copy_file(book / "book.css", out / "book.css", fs::copy_options::overwrite_existing);
    for (const auto& [img, from] : copies) {
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
