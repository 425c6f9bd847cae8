#include "io/json_locations.hpp"

#include "core/limits.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <vector>

namespace rt {

namespace {

// One pass over a JSON text. At the start of every value `visit(pointer, offset, scalar)`
// is called (offset of the key for an object member), and may stop the walk by returning
// true. Containers are tracked on an explicit stack, so depth costs memory, not stack.
class Walk {
public:
    // `scalar` is empty at a container's opening bracket; `depth` counts the containers
    // around the value.
    using Visit =
        std::function<bool(const std::string& pointer, std::size_t at, std::string_view scalar, std::size_t depth)>;

    Walk(std::string_view text, Visit visit) : s_(text), visit_(std::move(visit)) {}

    void run() {
        std::size_t at = 0;
        skip_space();
        at = i_;
        // Every iteration consumes at least one byte or ends, so any input terminates.
        while (true) {
            skip_space();
            if (at_end()) return;
            // A value begins here; `at` is where it is reported (its key, for a member).
            const char c = s_[i_];
            if (c == '{' || c == '[') {
                if (visit_(pointer_, at, {}, frames_.size())) return;
                frames_.push_back({c == '{', 0, pointer_.size()});
                ++i_;
                skip_space();
                if (peek() == (c == '{' ? '}' : ']')) {
                    ++i_;
                    frames_.pop_back();
                    if (!next(at)) return;
                    continue;
                }
                if (!enter(at)) return;
                continue;
            }
            const std::size_t begin = i_;
            if (c == '"') {
                string();
            } else {
                while (!at_end() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '-' ||
                                     s_[i_] == '+' || s_[i_] == '.'))
                    ++i_;
                if (i_ == begin) ++i_;  // a stray byte: step over it
            }
            if (visit_(pointer_, at, s_.substr(begin, i_ - begin), frames_.size())) return;
            if (!next(at)) return;
        }
    }

private:
    struct Frame {
        bool object;
        long long index;
        std::size_t pointer_size;  // of the container's own pointer
    };

    // Into the first (or next) element of the innermost container; sets `at`.
    bool enter(std::size_t& at) {
        Frame& f = frames_.back();
        pointer_.resize(f.pointer_size);
        skip_space();
        at = i_;
        if (f.object) {
            if (peek() != '"') return false;  // not JSON: stop
            pointer_ += '/';
            pointer_ += escape(string());
            skip_space();
            if (peek() != ':') return false;
            ++i_;
        } else {
            pointer_ += '/';
            pointer_ += std::to_string(f.index);
        }
        return true;
    }

    // After a value: a comma moves to the next element, a closing bracket leaves the
    // container. False when the document has ended.
    bool next(std::size_t& at) {
        while (!frames_.empty()) {
            skip_space();
            if (peek() == ',') {
                ++i_;
                ++frames_.back().index;
                return enter(at);
            }
            if (at_end()) return false;
            ++i_;  // the closing bracket (or, in text that is not JSON, whatever stands there)
            pointer_.resize(frames_.back().pointer_size);
            frames_.pop_back();
        }
        return false;
    }

    static std::string escape(const std::string& key) {  // RFC 6901
        std::string r;
        for (char c : key) r += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
        return r;
    }
    bool at_end() const { return i_ >= s_.size(); }
    char peek() const { return at_end() ? '\0' : s_[i_]; }
    void skip_space() {
        while (!at_end() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
    }
    // A string's value, with its escapes decoded as the parser decodes them, so that keys
    // match nlohmann's.
    std::string string() {
        std::string r;
        ++i_;  // opening quote
        while (!at_end() && s_[i_] != '"') {
            if (s_[i_] != '\\') {
                r += s_[i_++];
                continue;
            }
            ++i_;
            if (at_end()) break;
            const char e = s_[i_++];
            switch (e) {
                case 'b':
                    r += '\b';
                    break;
                case 'f':
                    r += '\f';
                    break;
                case 'n':
                    r += '\n';
                    break;
                case 'r':
                    r += '\r';
                    break;
                case 't':
                    r += '\t';
                    break;
                case 'u':
                    append_utf8(r, code_point());
                    break;
                default:
                    r += e;  // \" \\ \/
            }
        }
        if (!at_end()) ++i_;  // closing quote
        return r;
    }
    unsigned hex4() {
        unsigned v = 0;
        for (int k = 0; k < 4 && !at_end() && std::isxdigit(static_cast<unsigned char>(s_[i_])); ++k, ++i_) {
            const char h = char(std::tolower(static_cast<unsigned char>(s_[i_])));
            v = v * 16 + unsigned(h <= '9' ? h - '0' : h - 'a' + 10);
        }
        return v;
    }
    unsigned code_point() {  // after "\u"; joins a surrogate pair
        const unsigned hi = hex4();
        if (hi >= 0xD800 && hi < 0xDC00 && s_.substr(i_, 2) == "\\u") {
            i_ += 2;
            const unsigned lo = hex4();
            return 0x10000 + ((hi - 0xD800) << 10) + (lo - 0xDC00);
        }
        return hi;
    }
    static void append_utf8(std::string& r, unsigned cp) {
        if (cp < 0x80) {
            r += char(cp);
        } else if (cp < 0x800) {
            r += char(0xC0 | (cp >> 6));
            r += char(0x80 | (cp & 0x3F));
        } else if (cp < 0x10000) {
            r += char(0xE0 | (cp >> 12));
            r += char(0x80 | ((cp >> 6) & 0x3F));
            r += char(0x80 | (cp & 0x3F));
        } else {
            r += char(0xF0 | (cp >> 18));
            r += char(0x80 | ((cp >> 12) & 0x3F));
            r += char(0x80 | ((cp >> 6) & 0x3F));
            r += char(0x80 | (cp & 0x3F));
        }
    }

    std::string_view s_;
    Visit visit_;
    std::size_t i_ = 0;
    std::vector<Frame> frames_;
    std::string pointer_;
};

}  // namespace

TextPosition position_of(std::string_view text, std::size_t offset) {
    TextPosition p;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++p.line;
            p.column = 1;
        } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
            ++p.column;  // count characters, not UTF-8 continuation bytes
        }
    }
    return p;
}

std::optional<TextPosition> locate(std::string_view text, std::string_view pointer) {
    std::optional<std::size_t> found;
    Walk(text, [&](const std::string& p, std::size_t at, std::string_view, std::size_t) {
        if (p == pointer) found = at;
        return found.has_value();
    }).run();
    if (!found) return std::nullopt;
    return position_of(text, *found);
}

std::optional<JsonTextProblem> check_json_text(std::string_view text) {
    std::optional<JsonTextProblem> problem;
    Walk(text, [&](const std::string& p, std::size_t at, std::string_view scalar, std::size_t depth) {
        if (scalar.empty()) {  // a container opens: one level deeper
            if (double(depth + 1) > limits::json_depth.max)
                problem = JsonTextProblem{at, p, limits::refuse(limits::json_depth, double(depth + 1))};
        } else if (scalar.find_first_not_of("0123456789+-.eE") == std::string_view::npos) {
            const std::string number(scalar);
            const double v = std::strtod(number.c_str(), nullptr);
            if (std::isinf(v))
                problem = JsonTextProblem{at, p, "number " + number.substr(0, 40) + " is too large to hold"};
        }
        return problem.has_value();
    }).run();
    return problem;
}

}  // namespace rt
