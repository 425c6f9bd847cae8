#pragma once
// Positions in a JSON text, found by scanning the text itself: nlohmann::json keeps no
// positions, and a scene file's errors must say where they are. The scanner is iterative
// (no recursion, so no depth can overflow the stack) and safe on any bytes: for text that
// is not valid JSON it may find nothing, but it always ends.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace rt {

struct TextPosition {
    int line = 1;
    int column = 1;  // in characters, not bytes
};

// Line and column of a byte offset.
TextPosition position_of(std::string_view text, std::size_t offset);

// Where the value at a JSON pointer ("/surfaces/3/radius") begins; for an object member,
// where its key begins. Nothing if the text holds no such value.
std::optional<TextPosition> locate(std::string_view text, std::string_view pointer);

// What a JSON parser would accept but the lab must not: nesting deeper than
// limits::json_depth, or a number too large for a double ("1e400").
struct JsonTextProblem {
    std::size_t offset;
    std::string pointer;  // of the value
    std::string message;
};
std::optional<JsonTextProblem> check_json_text(std::string_view text);

}  // namespace rt
