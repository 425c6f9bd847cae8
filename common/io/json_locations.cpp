#include "io/json_locations.hpp"

#include <cctype>

namespace rt {

namespace {

class Walker {
public:
    Walker(const std::string& text, std::map<std::string, TextPosition>& out) : s_(text), out_(out) {}

    void value(const std::string& pointer) {
        skip_space();
        if (at_end()) return;
        const char c = s_[i_];
        if (c == '{') {
            items('}', [&](int) {
                const TextPosition key_pos = pos_;
                const std::string child = pointer + "/" + escape(string());
                out_[child] = key_pos;
                skip_space();
                advance();  // ':'
                value(child);
            });
        } else if (c == '[') {
            items(']', [&](int index) {
                const std::string child = pointer + "/" + std::to_string(index);
                out_[child] = pos_;
                value(child);
            });
        } else if (c == '"') {
            string();
        } else {
            while (!at_end() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '-' || s_[i_] == '+' ||
                                 s_[i_] == '.'))
                advance();
        }
    }

private:
    // The comma-separated members of an object or elements of an array, from the opening
    // bracket through `close`.
    template <class Item>
    void items(char close, Item&& item) {
        advance();
        skip_space();
        if (peek() == close) return advance();
        for (int index = 0; !at_end(); ++index) {
            skip_space();
            item(index);
            skip_space();
            if (peek() != ',') return advance();  // the closing bracket
            advance();
        }
    }

    static std::string escape(const std::string& key) {  // RFC 6901
        std::string r;
        for (char c : key) r += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
        return r;
    }
    bool at_end() const { return i_ >= s_.size(); }
    char peek() const { return at_end() ? '\0' : s_[i_]; }
    void advance() {
        if (at_end()) return;
        if (s_[i_] == '\n') {
            ++pos_.line;
            pos_.column = 1;
        } else if ((static_cast<unsigned char>(s_[i_]) & 0xC0) != 0x80) {
            ++pos_.column;  // count characters, not UTF-8 continuation bytes
        }
        ++i_;
    }
    void skip_space() {
        while (!at_end() && std::isspace(static_cast<unsigned char>(s_[i_]))) advance();
    }
    std::string string() {
        std::string r;
        advance();  // opening quote
        while (!at_end() && s_[i_] != '"') {
            if (s_[i_] == '\\') {
                advance();
                r += s_[i_];  // good enough for keys: escapes in keys are rare
            } else {
                r += s_[i_];
            }
            advance();
        }
        advance();  // closing quote
        return r;
    }

    const std::string& s_;
    std::map<std::string, TextPosition>& out_;
    std::size_t i_ = 0;
    TextPosition pos_;
};

}  // namespace

std::map<std::string, TextPosition> json_locations(const std::string& text) {
    std::map<std::string, TextPosition> out;
    Walker(text, out).value("");
    return out;
}

TextPosition position_of(const std::string& text, std::size_t offset) {
    TextPosition p;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++p.line;
            p.column = 1;
        } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
            ++p.column;
        }
    }
    return p;
}

}  // namespace rt
