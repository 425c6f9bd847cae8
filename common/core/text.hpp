#pragma once
// Messages are one line: a value quoted from an input (a JSON string with "\n" in it, the
// four bytes of an unknown PNG chunk) must not break that promise, or print bytes a
// terminal would interpret.
#include <cstddef>
#include <functional>
#include <iterator>
#include <string>
#include <string_view>

namespace rt {

// The text with every control character written as an escape ("\n", "\x1b"): one line,
// printable. Bytes of 0x80 and above (UTF-8) are kept.
inline std::string one_line(std::string_view text) {
    static constexpr char hex[] = "0123456789abcdef";
    std::string r;
    r.reserve(text.size());
    for (const char c : text) {
        const auto b = static_cast<unsigned char>(c);
        if (b >= 0x20 && b != 0x7f) {
            r += c;
        } else if (c == '\n') {
            r += "\\n";
        } else if (c == '\t') {
            r += "\\t";
        } else {
            r += "\\x";
            r += hex[b >> 4];
            r += hex[b & 15];
        }
    }
    return r;
}

// "a", "a or b", "a, b or c": the choices a message lists, each item as `say` gives it.
template <class Range, class Say = std::identity>
std::string or_list(const Range& items, Say say = {}) {
    std::string out;
    const std::size_t n = std::size(items);
    std::size_t k = 0;
    for (const auto& item : items) {
        out += k == 0 ? "" : k + 1 == n ? " or " : ", ";
        out += say(item);
        ++k;
    }
    return out;
}

}  // namespace rt
