#include "io/json_reader.hpp"

#include "core/text.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>

namespace rt {

using nlohmann::json;

JsonReader::JsonReader(const std::string& text, std::string filename, std::string base_dir, FileAccess access)
    : text_(text), filename_(std::move(filename)), base_dir_(std::move(base_dir)), access_(std::move(access)) {}

void JsonReader::fail(const std::string& pointer, const std::string& message) const {
    TextPosition p;
    std::string at = pointer;
    while (true) {
        if (const auto found = locate(text_, at)) {
            p = *found;
            break;
        }
        if (at.empty()) break;
        at = at.substr(0, at.rfind('/'));
    }
    throw SceneError(one_line(filename_ + ":" + std::to_string(p.line) + ":" + std::to_string(p.column) + ": " +
                              (pointer.empty() ? std::string("/") : pointer) + ": " + message));
}

Fields::Fields(const JsonReader& reader, const json& object, std::string pointer)
    : reader_(reader), object_(object), pointer_(std::move(pointer)), asked_(std::make_shared<Asked>()) {
    if (!object_.is_object()) reader_.fail(pointer_, "must be an object");
}

Fields::~Fields() {
    // Only the last copy checks, and not while a failure unwinds the reading.
    if (!asked_ || asked_.use_count() > 1 || asked_->done || std::uncaught_exceptions() > 0) return;
    std::fprintf(stderr, "internal error: %s was read without done(), so its unknown keys were not checked\n",
                 pointer_.empty() ? "/" : pointer_.c_str());
    std::abort();
}

void Fields::ask(const char* key) const {
    if (std::find(asked_->keys.begin(), asked_->keys.end(), key) == asked_->keys.end()) asked_->keys.emplace_back(key);
}

void Fields::done() const {
    asked_->done = true;
    for (const auto& [key, value] : object_.items()) {
        if (std::find(asked_->keys.begin(), asked_->keys.end(), key) != asked_->keys.end()) continue;
        // Sorted: the order keys were asked in can follow the order a compiler evaluates
        // function arguments in, and a message should not.
        std::vector<std::string> keys = asked_->keys;
        std::sort(keys.begin(), keys.end());
        std::string list;
        for (const std::string& a : keys) list += (list.empty() ? "" : ", ") + a;
        reader_.fail(pointer_ + "/" + key, "unknown key '" + key + "' (expected one of: " + list + ")");
    }
}

bool Fields::has(const char* key) const {
    ask(key);
    return object_.contains(key);
}

std::string Fields::pointer(const char* key) const {
    return *key ? pointer_ + "/" + key : pointer_;
}

void Fields::fail(const char* key, const std::string& message) const {
    reader_.fail(pointer(key), message);
}

const json& Fields::need(const char* key) const {
    ask(key);
    if (!object_.contains(key)) reader_.fail(pointer_, std::string("missing key '") + key + "'");
    return object_.at(key);
}

std::string Fields::text(const char* key) const {
    const json& v = need(key);
    if (!v.is_string()) fail(key, "must be a string");
    return v.get<std::string>();
}
std::string Fields::text(const char* key, const std::string& fallback) const {
    return has(key) ? text(key) : fallback;
}

double Fields::number_at(const json& v, const std::string& ptr, const limits::Range& range, bool as_float) const {
    if (!v.is_number()) reader_.fail(ptr, "must be a number");
    const double d = v.get<double>();
    // Every range of limits.hpp lies well inside float's, so a value in range stays finite
    // (and non-zero, where the range is) in the type it is stored in: a colour is a float
    // even when geometry is double. The second test says so where it matters.
    const double stored = as_float ? double(float(d)) : double(Real(d));
    if (!limits::contains(range, d) || !std::isfinite(stored) || (range.min > 0 && !(stored > 0)))
        reader_.fail(ptr, limits::refuse(range, d));
    return stored;
}
Real Fields::number(const char* key, const limits::Range& range) const {
    return Real(number_at(need(key), pointer(key), range, false));
}
Real Fields::number(const char* key, const limits::Range& range, Real fallback) const {
    return has(key) ? number(key, range) : fallback;
}

Real Fields::length(const char* key) const {
    return number(key, limits::length);
}
Real Fields::length(const char* key, Real fallback) const {
    return has(key) ? length(key) : fallback;
}

int Fields::integer(const char* key, const limits::Range& range) const {
    const json& v = need(key);
    if (!v.is_number_integer()) fail(key, "must be a whole number");
    const auto n = v.get<long long>();
    if (!limits::contains(range, double(n))) fail(key, limits::refuse(range, double(n)));
    return int(n);
}
int Fields::integer(const char* key, const limits::Range& range, int fallback) const {
    return has(key) ? integer(key, range) : fallback;
}

Vec3 Fields::vec3_at(const json& v, const std::string& ptr) const {
    if (!v.is_array() || v.size() != 3) reader_.fail(ptr, "must be an array of 3 numbers");
    Vec3 r;
    for (int k = 0; k < 3; ++k)
        r[k] = Real(number_at(v[std::size_t(k)], ptr + "/" + std::to_string(k), limits::coordinate, false));
    return r;
}
Vec3 Fields::vec3(const char* key) const {
    return vec3_at(need(key), pointer(key));
}
Vec3 Fields::vec3(const char* key, const Vec3& fallback) const {
    return has(key) ? vec3(key) : fallback;
}

Vec3 Fields::direction(const char* key) const {
    const Vec3 d = vec3(key);
    if (d == Vec3(0)) fail(key, "must not be zero");
    return d;
}

Color Fields::color(const char* key, const limits::Range& range, const Color& fallback) const {
    if (!has(key)) return fallback;
    const json& v = need(key);
    const std::string ptr = pointer(key);
    if (!v.is_array() || v.size() != 3) fail(key, "must be an array of 3 numbers");
    Color c;
    for (int k = 0; k < 3; ++k) c[k] = float(number_at(v[std::size_t(k)], ptr + "/" + std::to_string(k), range, true));
    return c;
}

std::vector<Vec3> Fields::points(const char* key, const limits::Range& range) const {
    const json& v = need(key);
    const auto lo = std::size_t(range.min), hi = std::size_t(range.max);
    if (!v.is_array()) fail(key, "must be an array of points");
    if (v.size() < lo || v.size() > hi)
        fail(key, lo == hi ? "must be an array of " + std::to_string(lo) + " points"
                           : "must be an array of points: " + limits::refuse(range, double(v.size())));
    std::vector<Vec3> result;
    result.reserve(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) result.push_back(vec3_at(v[i], pointer(key) + "/" + std::to_string(i)));
    return result;
}

bool Fields::is_number(const char* key) const {
    return has(key) && object_.at(key).is_number();
}

std::vector<Real> Fields::numbers(const char* key, std::size_t count, const limits::Range& range) const {
    const json& v = need(key);
    if (!v.is_array() || v.size() != count) fail(key, "must be an array of " + std::to_string(count) + " numbers");
    std::vector<Real> result;
    for (std::size_t k = 0; k < count; ++k)
        result.push_back(Real(number_at(v[k], pointer(key) + "/" + std::to_string(k), range, false)));
    return result;
}

bool Fields::flag(const char* key, bool fallback) const {
    if (!has(key)) return fallback;
    const json& v = need(key);
    if (!v.is_boolean()) fail(key, "must be true or false");
    return v.get<bool>();
}

Fields Fields::object(const char* key) const {
    return Fields(reader_, need(key), pointer(key));
}

std::vector<Fields> Fields::objects(const char* key) const {
    const json& v = need(key);
    if (!v.is_array()) fail(key, "must be an array of objects");
    std::vector<Fields> result;
    result.reserve(v.size());
    for (std::size_t i = 0; i < v.size(); ++i)
        result.emplace_back(reader_, v[i], pointer(key) + "/" + std::to_string(i));
    return result;
}

std::vector<std::pair<std::string, Fields>> Fields::named_objects(const char* key) const {
    const json& v = need(key);
    if (!v.is_object()) fail(key, "must be an object");
    std::vector<std::pair<std::string, Fields>> result;
    result.reserve(v.size());
    for (const auto& [name, value] : v.items())
        result.emplace_back(name, Fields(reader_, value, pointer(key) + "/" + name));
    return result;
}

std::string Fields::file(const char* key) const {
    const std::string name = text(key);
    try {
        return reader_.access().resolve(name, reader_.base_dir());
    } catch (const std::runtime_error& e) {
        fail(key, e.what());
    }
}

}  // namespace rt
