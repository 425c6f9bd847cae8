#pragma once
// Reading a scene file's JSON, one object at a time, so that every problem becomes one line
// "FILE:LINE:COLUMN: /json/pointer: what is wrong" pointing at the offending key. The scene
// modules (io/types/) see only Fields, never the JSON library.
#include "core/real.hpp"
#include "geometry/limits.hpp"
#include "io/json_locations.hpp"

#include <nlohmann/json_fwd.hpp>

#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

namespace rt {

// A scene file problem, as one line.
struct SceneError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The whole document: where each value is, and the file's name and directory.
class JsonReader {
public:
    JsonReader(const std::string& text, std::string filename, std::string base_dir);

    // Throws SceneError at the nearest enclosing value that has a position (a missing key
    // has none).
    [[noreturn]] void fail(const std::string& pointer, const std::string& message) const;
    const std::string& base_dir() const { return base_dir_; }

private:
    std::string text_;  // positions are looked up in it only when something fails
    std::string filename_;
    std::string base_dir_;
};

// One JSON object of the scene file, read key by key. A getter without a fallback requires
// its key; every getter checks the value's type and range.
class Fields {
public:
    // Fails unless `object` is a JSON object.
    Fields(const JsonReader& reader, const nlohmann::json& object, std::string pointer);

    // Fails on the first key not in `allowed`, listing the allowed ones.
    void only(std::initializer_list<const char*> allowed) const;
    void only(const std::vector<const char*>& allowed) const;

    bool has(const char* key) const;
    std::string text(const char* key) const;
    std::string text(const char* key, const std::string& fallback) const;
    // Every number is checked against its range of limits.hpp in the type it is stored in.
    Real number(const char* key, const limits::Range& range) const;
    Real number(const char* key, const limits::Range& range, Real fallback) const;
    // A radius, a size, a scale: limits::length.
    Real length(const char* key) const;
    Real length(const char* key, Real fallback) const;
    int integer(const char* key, const limits::Range& range) const;
    int integer(const char* key, const limits::Range& range, int fallback) const;
    // A point or a vector, each component a limits::coordinate.
    Vec3 vec3(const char* key) const;
    Vec3 vec3(const char* key, const Vec3& fallback) const;
    // A direction: a vec3 that is not zero.
    Vec3 direction(const char* key) const;
    // A colour, each component in `range` (limits::reflectance or limits::radiance).
    Color color(const char* key, const limits::Range& range, const Color& fallback) const;
    // An array of points whose length is in `range`.
    std::vector<Vec3> points(const char* key, const limits::Range& range) const;
    bool flag(const char* key, bool fallback) const;
    bool is_number(const char* key) const;
    // An array of objects, each read as Fields of its own.
    std::vector<Fields> objects(const char* key) const;
    // A file name, relative to the scene file's directory unless absolute.
    std::string file(const char* key) const;

    // Fails at `key` (or at the object itself for an empty key).
    [[noreturn]] void fail(const char* key, const std::string& message) const;
    std::string pointer(const char* key = "") const;
    const nlohmann::json& value() const { return object_; }
    const JsonReader& reader() const { return reader_; }

private:
    const nlohmann::json& need(const char* key) const;
    double number_at(const nlohmann::json& value, const std::string& pointer, const limits::Range& range,
                     bool as_float) const;
    Vec3 vec3_at(const nlohmann::json& value, const std::string& pointer) const;

    const JsonReader& reader_;
    const nlohmann::json& object_;
    std::string pointer_;
};

}  // namespace rt
