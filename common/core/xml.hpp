#pragma once
// Text put into the SVG the library and its tools write (the book's diagrams, a pixel's ray
// tree): one escape, so that a name with "<" or "&" in it, or a control character from a
// scene file, cannot break the document. Its own header, not text.hpp, which more of the
// tree includes than the few files that write XML.
#include <string>
#include <string_view>

namespace rt {

// The text with XML's four special characters written as entities, for an element's text or
// a double-quoted attribute. Control characters are dropped: XML 1.0 does not allow most of
// them anywhere, and the rest (tab, newline) a title or a label does not need. Bytes of 0x80
// and above (UTF-8: a Greek letter, a subscript) are kept.
inline std::string xml_escape(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '&')
            out += "&amp;";
        else if (c == '"')
            out += "&quot;";
        else if (static_cast<unsigned char>(c) >= 0x20)
            out += c;
    }
    return out;
}

}  // namespace rt
