// libFuzzer target: the scene-file reader, from JSON text to a Scene. Every input must end
// in a Scene or a SceneError (one line, exit 2 in the programs): any other exception, a
// crash, a leak or a sanitizer report is a bug.
#include "fuzz_support.hpp"
#include "io/scene_file.hpp"

#include <nlohmann/json.hpp>

namespace {

// Inputs that are valid but slow by design (a terrain of 2048x2048 cells is 8 million
// triangles; an icosphere of 7 subdivisions, the most allowed, 327,680, whose tree took over
// the run's 10 s per input under ASan) would crowd out everything else: they are skipped, not
// loaded. Mesh files have their own target (obj.cpp), and must not make this one read the
// machine's files.
bool worth_loading(const nlohmann::json& j) {
    if (j.is_array()) {
        for (const auto& v : j)
            if (!worth_loading(v)) return false;
    } else if (j.is_object()) {
        for (const auto& [key, v] : j.items()) {
            if (key == "file") return false;
            if ((key == "cells" || key == "count") && v.is_number() && v.get<double>() > 16) return false;
            if (key == "subdivisions" && v.is_number() && v.get<double>() > 5) return false;  // 20,480 triangles
            if (!worth_loading(v)) return false;
        }
    }
    return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text = rt::fuzz::text(data, size);
    if (!rt::check_json_text(text)) {  // deep or huge-number documents go straight to the loader
        const auto j = nlohmann::json::parse(text, nullptr, false);
        if (!j.is_discarded() && !worth_loading(j)) return -1;
    }
    try {
        const rt::Scene scene = rt::load_scene_text(text, "fuzz.json", "/nonexistent");
        rt::fuzz::check(scene.surfaces.size() < (1u << 24), "surface count");
    } catch (const rt::SceneError& e) {
        rt::fuzz::one_line(e.what());
    }
    return 0;
}
