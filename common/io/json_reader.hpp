#pragma once
// Reading a scene file's JSON, one object at a time, so that every problem becomes one line
// "FILE:LINE:COLUMN: /json/pointer: what is wrong" pointing at the offending key. The scene
// modules (io/types/) see only Fields, never the JSON library.
#include "core/names.hpp"
#include "core/real.hpp"
#include "geometry/limits.hpp"
#include "io/file_access.hpp"
#include "io/json_locations.hpp"

#include <nlohmann/json_fwd.hpp>

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rt {

// A scene file problem, as one line.
struct SceneError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The whole document: where each value is, the file's name and directory, and which files
// it may name.
class JsonReader {
public:
    JsonReader(const std::string& text, std::string filename, std::string base_dir, FileAccess access = {});

    // Throws SceneError at the nearest enclosing value that has a position (a missing key
    // has none).
    [[noreturn]] void fail(const std::string& pointer, const std::string& message) const;
    const std::string& base_dir() const { return base_dir_; }
    const FileAccess& access() const { return access_; }

private:
    std::string text_;  // positions are looked up in it only when something fails
    std::string filename_;
    std::string base_dir_;
    FileAccess access_;
};

// One JSON object of the scene file, read key by key. A getter without a fallback requires
// its key; every getter checks the value's type and range. Every key a reader asks about
// (has, or any getter) is remembered, and done() refuses the keys nobody asked about: what
// a reader reads is what it accepts, with no separate list of keys to keep in step (pbrt's
// lookedUp / ReportUnused).
class Fields {
public:
    // Fails unless `object` is a JSON object.
    Fields(const JsonReader& reader, const nlohmann::json& object, std::string pointer);
    // A Fields read to the end without done() is a reader that would accept any key: the
    // program stops there, so the first test that reads such an object finds it.
    ~Fields();
    Fields(const Fields&) = default;
    Fields(Fields&&) = default;

    // After reading: fails on the first key no getter asked about, listing those asked
    // (sorted).
    void done() const;

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
    // An array of `count` numbers, each in `range` (a shutter interval).
    std::vector<Real> numbers(const char* key, std::size_t count, const limits::Range& range) const;
    // One of an enum's names (core/names.hpp); `what` names the kind in the message:
    // unknown WHAT "x" (expected a, b or c).
    template <class E, std::size_t N>
    E choice(const char* key, const Names<E, N>& names, const char* what) const {
        const std::string name = text(key);
        if (const auto found = names.find(name)) return *found;
        fail(key, std::string("unknown ") + what + " \"" + name + "\" (expected " + names.list() + ")");
    }
    template <class E, std::size_t N>
    E choice(const char* key, const Names<E, N>& names, const char* what, E fallback) const {
        return has(key) ? choice(key, names, what) : fallback;
    }
    // An object, read as Fields of its own.
    Fields object(const char* key) const;
    // An array of objects, each read as Fields of its own.
    std::vector<Fields> objects(const char* key) const;
    // An object whose keys are names the file chooses (/materials, /shapes): each value read
    // as Fields of its own, with its name.
    std::vector<std::pair<std::string, Fields>> named_objects(const char* key) const;
    // A file name, relative to the scene file's directory unless absolute: the path to open.
    // Fails at the key, before the file is opened, for a file the scene may not name
    // (FileAccess).
    std::string file(const char* key) const;

    // Fails at `key` (or at the object itself for an empty key).
    [[noreturn]] void fail(const char* key, const std::string& message) const;
    std::string pointer(const char* key = "") const;

private:
    // The keys asked about, in the order asked, shared by the copies of one Fields.
    struct Asked {
        std::vector<std::string> keys;
        bool done = false;
    };
    void ask(const char* key) const;
    const nlohmann::json& need(const char* key) const;
    double number_at(const nlohmann::json& value, const std::string& pointer, const limits::Range& range,
                     bool as_float) const;
    Vec3 vec3_at(const nlohmann::json& value, const std::string& pointer) const;

    const JsonReader& reader_;
    const nlohmann::json& object_;
    std::string pointer_;
    std::shared_ptr<Asked> asked_;
};

}  // namespace rt
