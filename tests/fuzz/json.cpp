// libFuzzer target: the JSON scanner behind every scene-file message (io/json_locations).
// On any bytes it must end without a crash; on a document the parser accepts and the scanner
// passes, every member and element the parser sees must be located.
#include "fuzz_support.hpp"
#include "io/json_locations.hpp"

#include <nlohmann/json.hpp>

namespace {

using nlohmann::json;

void locate_all(const std::string& text, const json& value, const json::json_pointer& at, int depth) {
    rt::fuzz::check(rt::locate(text, at.to_string()).has_value() || at.empty(),
                    "a value the parser sees is not located");
    if (depth == 0) return;
    if (value.is_object())
        for (const auto& [key, v] : value.items()) locate_all(text, v, at / key, depth - 1);
    else if (value.is_array())
        for (std::size_t i = 0; i < value.size() && i < 8; ++i) locate_all(text, value[i], at / i, depth - 1);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text = rt::fuzz::text(data, size);
    (void)rt::locate(text, "/surfaces/0/radius");
    (void)rt::position_of(text, size / 2);
    if (const auto problem = rt::check_json_text(text)) {
        rt::fuzz::check(problem->offset <= size, "problem offset past the end");
        rt::fuzz::one_line(problem->message.c_str());
        return 0;
    }
    const json doc = json::parse(text, nullptr, false);
    if (!doc.is_discarded()) locate_all(text, doc, json::json_pointer(), 3);
    return 0;
}
