// A strict, path-aware view on parsed JSON for the scene loader. Every value knows its
// JSON path ("shapes[3].transform.rotate.axis"), so each error can name exactly what is
// wrong; objects remember which keys were read, so misspelt fields are reported instead
// of silently ignored. All errors are photon::SceneError(path, message).
#pragma once
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>
#include <nlohmann/json.hpp>
#include <photon/vec.h>
#include "scene/scene_loader.h"

namespace photon {

// Document order matters: materials keep the order they were written in, and the first
// unknown field reported is the first one in the file.
using Json = nlohmann::ordered_json;

// Parses a scene document. Malformed JSON: SceneError("", "malformed JSON: <reason>").
// Also refuses duplicate keys ("duplicate field", which JSON parsers otherwise resolve
// silently by keeping one) and numbers too large for a double ("must be a finite
// number"), both at the path where they occur.
Json parseJsonDocument(const std::string& text);

// Appends an object key or array index to a path.
std::string childPath(const std::string& path, std::string_view key);
std::string elementPath(const std::string& path, size_t index);

// An interval a number must lie in; describe() gives the error text ("must be > 0").
struct Range {
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    bool loOpen = true, hiOpen = true;

    static Range any() { return {}; }
    static Range positive() { return {0, std::numeric_limits<double>::infinity(), true, true}; }
    static Range nonNegative() { return {0, std::numeric_limits<double>::infinity(), false, true}; }
    static Range closed(double lo, double hi) { return {lo, hi, false, false}; }
    static Range open(double lo, double hi) { return {lo, hi, true, true}; }
    static Range openClosed(double lo, double hi) { return {lo, hi, true, false}; }
    bool contains(double v) const;
    std::string describe() const;
};

class JsonObject;

class JsonValue {
public:
    JsonValue(const Json& json, std::string path) : json_(&json), path_(std::move(path)) {}
    const Json& json() const { return *json_; }
    const std::string& path() const { return path_; }
    [[noreturn]] void fail(const std::string& message) const;

    // A finite number that fits a float (the engine computes in floats) inside `range`.
    float number(const Range& range = Range::any()) const;
    // An integral number in [lo, hi]; 3.0 counts as an integer (JSON has one number type).
    int64_t integer(int64_t lo, int64_t hi) const;
    uint64_t unsignedInteger() const;  // any integer in [0, 2^64)
    bool boolean() const;
    const std::string& string() const;
    // Index of the string among `names`; `what` names the kind in the message:
    // `unknown type "cone" (expected one of quad, sphere, mesh)`.
    size_t choice(std::initializer_list<std::string_view> names, std::string_view what = "value") const;
    // Arrays of 3 (or 2) finite numbers, each inside `range` (checked at "path[i]").
    Vec3 vec3(const Range& range = Range::any()) const;
    Vec2 vec2(const Range& range = Range::any()) const;
    // A direction or axis: refuses [0, 0, 0]; returned normalised.
    Vec3 direction() const;
    std::vector<JsonValue> elements() const;  // "must be an array"
    JsonObject object() const;                // "must be an object"

private:
    const Json* json_;
    std::string path_;
};

// An object being read: getters mark keys as read; finish() reports any key no getter
// asked for. Call finish() once every field has been read.
class JsonObject {
public:
    JsonObject(const Json& json, std::string path) : json_(&json), path_(std::move(path)) {}
    const std::string& path() const { return path_; }
    [[noreturn]] void fail(const std::string& message) const;

    bool has(std::string_view key) const;
    std::optional<JsonValue> optional(std::string_view key);
    JsonValue required(std::string_view key);  // "missing required field" at path.key
    // All members in document order, all marked as read (for name → value maps).
    std::vector<std::pair<std::string, JsonValue>> members();
    void finish() const;  // "unknown field" at the first key not read

    // Optional fields with their defaults.
    float number(std::string_view key, float fallback, const Range& range = Range::any());
    int64_t integer(std::string_view key, int64_t fallback, int64_t lo, int64_t hi);
    bool boolean(std::string_view key, bool fallback);
    Vec3 vec3(std::string_view key, Vec3 fallback, const Range& range = Range::any());
    size_t choice(std::string_view key, size_t fallback, std::initializer_list<std::string_view> names,
                  std::string_view what = "value");

private:
    const Json* json_;
    std::string path_;
    std::set<std::string, std::less<>> read_;
};

}  // namespace photon
