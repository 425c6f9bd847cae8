#pragma once
// Line and column of every value in a JSON text, by JSON pointer ("/surfaces/3/radius"),
// so that a scene file's errors can say where they are. nlohmann::json keeps no positions.
#include <map>
#include <string>

namespace rt {

struct TextPosition {
    int line = 1;
    int column = 1;
};

// For an object member, the position of its key; for an array element, of the element.
// The text must be valid JSON (parse it first).
std::map<std::string, TextPosition> json_locations(const std::string& text);

// Line and column of a byte offset.
TextPosition position_of(const std::string& text, std::size_t offset);

}  // namespace rt
