// rtlab-figures: the book's diagrams, drawn by the library itself.
//
//   rtlab-figures --root SRC --out OUT   writes OUT/chNN/figures/NAME.svg for every description
//                                        SRC/chapters/chNN_*/figures/NAME.json
//   rtlab-figures --root SRC --list      prints chNN/figures/NAME.svg, one per description
//
// A description is a small JSON object: {"kind": "ray-sphere", "caption": "...", inputs...}.
// The kind names a function that builds the real objects from the inputs (a Sphere, a Polygon,
// a camera's View) and asks the library's own code where the hits, normals and rays are, so
// a diagram cannot drift from the code the chapter teaches. Only the inputs are typed by hand.
//
// How to add a figure kind:
//   1. tools/figures/NAME.cpp: `Canvas NAME(const rt::Fields& in)`. Read every input through
//      `in` (in.vec3, in.number, in.points, ...; unknown keys are refused for you), build the
//      library's objects, call the library for every point, direction and answer you draw,
//      and draw them on a Canvas (svg.hpp) in world units: it frames the picture itself. Use
//      the palette's Ink for what a thing is (Ink::camera for a camera ray, Ink::shadow for a
//      shadow ray, ...), never a colour. Refuse impossible inputs with in.fail(key, why).
//   2. One line in RTLAB_FIGURE_KINDS (kinds.hpp): X("the-kind", NAME).
//   3. The file is picked up by tools/CMakeLists.txt (a glob of tools/figures/*.cpp).
//   4. A description chapters/chNN_*/figures/FIG.json, and `![caption](../chNN/figures/FIG.svg)`
//      in the chapter's book text (the ctest `figures` checks that both exist; raise
//      RTLAB_FIGURES_MIN in tests/figures.cmake to the new count). Look at it:
//      rsvg-convert -o /tmp/fig.png out/chNN/figures/FIG.svg (librsvg2-bin).
// Shared helpers (kinds.hpp, svg.hpp): flat() puts a point of the plane z = 0 on the page,
// View3 draws 3D from a chosen direction, number() and degrees_between() write labels,
// spheres_of() reads the circles a structure is built over, pixel_samples_of() one pixel's
// samples, ray_of() the one ray a figure follows.
#include "kinds.hpp"
#include "render/antialiasing.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace figures {

std::string number(double v, int digits) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    std::string s = buf;
    if (s == "-0") s = "0";
    // A typographic minus: "−0.5" reads better than "-0.5" in a label.
    if (!s.empty() && s[0] == '-') s = "\u2212" + s.substr(1);
    return s;
}

double degrees_between(const rt::Vec3& a, const rt::Vec3& b) {
    const double c = double(glm::dot(rt::unit_vector(a), rt::unit_vector(b)));
    return std::acos(std::clamp(c, -1.0, 1.0)) * 180 / M_PI;
}

std::vector<rt::Sphere> spheres_of(const rt::Fields& in) {
    std::vector<rt::Sphere> spheres;
    for (const rt::Fields& s : in.objects("spheres")) {
        spheres.emplace_back(s.vec3("center"), s.length("radius"));
        s.done();
    }
    return spheres;
}

PixelSamples pixel_samples_of(const rt::Fields& in, int most) {
    const int count = in.integer("samples", {"samples", 1, double(most), "", ""});
    const auto side = rt::pattern_side(count);
    if (!side) in.fail("samples", "must be a square number (4, 9, 16, ...)");
    const auto seed = std::uint64_t(in.integer("seed", {"seed", 0, 1 << 30, "", ""}));
    const auto pixel = std::uint64_t(in.integer("pixel", {"pixel", 0, 1 << 30, "", ""}));
    return {count, *side, seed, pixel};
}

DrawnRay ray_of(const rt::Fields& in) {
    const rt::Fields r = in.object("ray");
    const rt::Ray ray{r.vec3("origin"), r.direction("direction")};
    const rt::Real t_end = r.length("t_end");
    r.done();
    return {ray, t_end};
}

}  // namespace figures

namespace {

using Draw = figures::Canvas (*)(const rt::Fields&);

const std::map<std::string, Draw>& kinds() {
#define RTLAB_FIGURE_ENTRY(name, function) {name, &figures::function},
    static const std::map<std::string, Draw> table{RTLAB_FIGURE_KINDS(RTLAB_FIGURE_ENTRY)};
#undef RTLAB_FIGURE_ENTRY
    return table;
}

struct Description {
    fs::path file;     // SRC/chapters/chNN_*/figures/NAME.json
    std::string name;  // chNN/figures/NAME.svg
};

// Every description under SRC/chapters, in order of their output names.
std::vector<Description> descriptions(const fs::path& root) {
    std::vector<Description> found;
    const fs::path chapters = root / "chapters";
    if (!fs::is_directory(chapters)) throw std::runtime_error(chapters.string() + ": no such directory");
    for (const auto& ch : fs::directory_iterator(chapters)) {
        const std::string dir = ch.path().filename().string();
        if (!ch.is_directory() || dir.size() < 5 || dir.rfind("ch", 0) != 0 || dir[4] != '_') continue;
        if (!fs::is_directory(ch.path() / "figures")) continue;
        for (const auto& f : fs::directory_iterator(ch.path() / "figures"))
            if (f.path().extension() == ".json")
                found.push_back({f.path(), dir.substr(0, 4) + "/figures/" + f.path().stem().string() + ".svg"});
    }
    std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
    return found;
}

// One description to its SVG; a bad one throws rt::SceneError with the one line to print.
std::string render(const fs::path& file, const std::string& shown) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    if (!in) throw rt::SceneError(shown + ": cannot read the file");
    const std::string text = buffer.str();
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        std::string what = e.what();
        const auto colon = what.rfind(": ");  // drop nlohmann's "[json.exception...]" prefix
        if (colon != std::string::npos) what = what.substr(colon + 2);
        throw rt::SceneError(shown + ": /: not valid JSON: " + what);
    }
    const rt::JsonReader reader(text, shown, file.parent_path().string());
    const rt::Fields top(reader, doc, "");
    const std::string kind = top.text("kind");
    const auto found = kinds().find(kind);
    if (found == kinds().end()) {
        std::string list;
        for (const auto& [name, draw] : kinds()) list += (list.empty() ? "" : ", ") + name;
        top.fail("kind", "unknown figure kind \"" + kind + "\" (expected one of: " + list + ")");
    }
    const std::string caption = top.text("caption");
    if (caption.empty()) top.fail("caption", "must not be empty: it is the figure's title");
    try {
        const figures::Canvas canvas = found->second(top);
        top.done();
        return canvas.svg(caption);
    } catch (const std::invalid_argument& e) {  // the library refused an object built from the inputs
        top.fail("", e.what());
    }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"rtlab-figures: the book's diagrams, drawn by the library itself"};
    std::string root = ".", out;
    bool list = false;
    app.add_option("--root", root, "the lab's source tree (descriptions in chapters/chNN_*/figures/*.json)");
    app.add_option("--out", out, "where chNN/figures/NAME.svg are written");
    app.add_flag("--list", list, "print chNN/figures/NAME.svg for every description, and nothing else");
    try {
        app.parse(argc, argv);
        if (!list && out.empty()) throw CLI::RequiredError("--out (or --list)");
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    try {
        const auto all = descriptions(root);
        if (list) {
            for (const auto& d : all) std::cout << d.name << '\n';
            return 0;
        }
        for (const auto& d : all) {
            const std::string svg = render(d.file, fs::relative(d.file, root).string());
            const fs::path target = fs::path(out) / d.name;
            fs::create_directories(target.parent_path());
            std::ofstream(target, std::ios::binary) << svg;
        }
        std::cout << "rtlab-figures: " << all.size() << " figures in " << out << '\n';
    } catch (const std::exception& e) {
        std::cerr << e.what() << '\n';
        return 2;
    }
    return 0;
}
