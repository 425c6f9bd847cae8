#include "io/json_reader.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>

namespace rt {

using nlohmann::json;

JsonReader::JsonReader(const std::string& text, std::string filename, std::string base_dir)
    : locations_(json_locations(text)), filename_(std::move(filename)), base_dir_(std::move(base_dir)) {}

void JsonReader::fail(const std::string& pointer, const std::string& message) const {
    TextPosition p;
    std::string at = pointer;
    while (true) {
        auto it = locations_.find(at);
        if (it != locations_.end()) {
            p = it->second;
            break;
        }
        if (at.empty()) break;
        at = at.substr(0, at.rfind('/'));
    }
    throw SceneError(filename_ + ":" + std::to_string(p.line) + ":" + std::to_string(p.column) + ": " +
                     (pointer.empty() ? std::string("/") : pointer) + ": " + message);
}

Fields::Fields(const JsonReader& reader, const json& object, std::string pointer)
    : reader_(reader), object_(object), pointer_(std::move(pointer)) {
    if (!object_.is_object()) reader_.fail(pointer_, "must be an object");
}

void Fields::only(const std::vector<const char*>& allowed) const {
    for (const auto& [key, value] : object_.items()) {
        bool ok = false;
        for (const char* a : allowed) ok |= key == a;
        if (ok) continue;
        std::string list;
        for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
        reader_.fail(pointer_ + "/" + key, "unknown key '" + key + "' (expected one of: " + list + ")");
    }
}
void Fields::only(std::initializer_list<const char*> allowed) const {
    only(std::vector<const char*>(allowed));
}

bool Fields::has(const char* key) const {
    return object_.contains(key);
}

std::string Fields::pointer(const char* key) const {
    return *key ? pointer_ + "/" + key : pointer_;
}

void Fields::fail(const char* key, const std::string& message) const {
    reader_.fail(pointer(key), message);
}

const json& Fields::need(const char* key) const {
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

Real Fields::number_at(const json& v, const std::string& ptr) const {
    if (!v.is_number()) reader_.fail(ptr, "must be a number");
    const double d = v.get<double>();
    if (!std::isfinite(d)) reader_.fail(ptr, "must be finite");
    return Real(d);
}
Real Fields::number(const char* key) const {
    return number_at(need(key), pointer(key));
}
Real Fields::number(const char* key, Real fallback) const {
    return has(key) ? number(key) : fallback;
}

Real Fields::positive(const char* key) const {
    const Real v = number(key);
    if (!(v > 0)) fail(key, "must be > 0");
    return v;
}
Real Fields::positive(const char* key, Real fallback) const {
    return has(key) ? positive(key) : fallback;
}

int Fields::integer(const char* key, const limits::Range& range) const {
    const json& v = need(key);
    if (!v.is_number_integer()) fail(key, "must be a whole number");
    const auto n = v.get<long long>();
    if (n < range.min || n > range.max)
        fail(key,
             std::string(range.name) + " must be in " + std::to_string(range.min) + ".." + std::to_string(range.max));
    return int(n);
}
int Fields::integer(const char* key, const limits::Range& range, int fallback) const {
    return has(key) ? integer(key, range) : fallback;
}

Vec3 Fields::vec3_at(const json& v, const std::string& ptr) const {
    if (!v.is_array() || v.size() != 3) reader_.fail(ptr, "must be an array of 3 numbers");
    return Vec3(number_at(v[0], ptr + "/0"), number_at(v[1], ptr + "/1"), number_at(v[2], ptr + "/2"));
}
Vec3 Fields::vec3(const char* key) const {
    return vec3_at(need(key), pointer(key));
}
Vec3 Fields::vec3(const char* key, const Vec3& fallback) const {
    return has(key) ? vec3(key) : fallback;
}

Color Fields::color(const char* key, const Color& fallback) const {
    if (!has(key)) return fallback;
    const Vec3 c = vec3(key);
    if (c.x < 0 || c.y < 0 || c.z < 0) fail(key, "colour components must be >= 0");
    return Color(c);
}

std::vector<Vec3> Fields::points(const char* key, const limits::Range& range) const {
    const json& v = need(key);
    const auto lo = std::size_t(range.min), hi = std::size_t(range.max);
    if (!v.is_array()) fail(key, "must be an array of points");
    if (v.size() < lo || v.size() > hi)
        fail(key, lo == hi ? "must be an array of " + std::to_string(lo) + " points"
                           : "must be an array of " + std::to_string(lo) + ".." + std::to_string(hi) + " points (" +
                                 range.name + "), not " + std::to_string(v.size()));
    std::vector<Vec3> result;
    result.reserve(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) result.push_back(vec3_at(v[i], pointer(key) + "/" + std::to_string(i)));
    return result;
}

std::string Fields::file(const char* key) const {
    std::filesystem::path path = text(key);
    if (path.is_relative()) path = std::filesystem::path(reader_.base_dir()) / path;
    return path.string();
}

}  // namespace rt
