#include "scene/json_reader.h"
#include <algorithm>
#include <cctype>
#include <vector>
#include <cmath>
#include <cstdio>
#include <unordered_set>

namespace photon {

namespace {

// Builds the document like nlohmann's own DOM parser, but keeps track of where it is so
// that the problems nlohmann resolves silently or reports without a location (duplicate
// keys, 1e999) become SceneErrors at a JSON path.
class SceneSax : public nlohmann::json_sax<Json> {
public:
    Json root;

    bool null() override { return value(nullptr); }
    bool boolean(bool v) override { return value(v); }
    bool number_integer(number_integer_t v) override { return value(v); }
    bool number_unsigned(number_unsigned_t v) override { return value(v); }
    bool number_float(number_float_t v, const string_t&) override { return value(v); }
    bool string(string_t& v) override { return value(std::move(v)); }
    bool binary(binary_t& v) override { return value(Json::binary(std::move(v))); }
    bool start_object(std::size_t) override { return open(Json::object()); }
    bool start_array(std::size_t) override { return open(Json::array()); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }

    bool key(string_t& k) override {
        Frame& top = stack_.back();
        if (!top.keys.insert(k).second) throw SceneError(currentPath(k), "duplicate field");
        top.key = k;
        return true;
    }

    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
        // 406: a number literal outside the range of a double (nlohmann would make it inf).
        if (e.id == 406) throw SceneError(currentPath({}), "must be a finite number");
        std::string what = e.what();
        // Drop the "[json.exception.parse_error.101] " prefix: it means nothing to users.
        if (auto end = what.find("] "); what.starts_with("[json.exception.") && end != std::string::npos)
            what.erase(0, end + 2);
        throw SceneError("", "malformed JSON: " + what);
    }

private:
    // Scene files are shallow (an inline mesh vertex is 5 levels down); the limit keeps
    // adversarial input from growing the stack or the path strings without bound.
    static constexpr size_t kMaxDepth = 64;

    struct Frame {
        Json* container;
        std::string key;                      // objects: the key whose value is being read
        std::unordered_set<std::string> keys;  // objects: the keys seen so far
    };

    // Where the next value goes; for arrays it is appended.
    Json* slot(Json&& v) {
        if (stack_.empty()) {
            root = std::move(v);
            return &root;
        }
        Frame& top = stack_.back();
        if (top.container->is_array()) {
            top.container->push_back(std::move(v));
            return &top.container->back();
        }
        // ordered_json's operator[] searches its members linearly, which would make an
        // object with n keys cost O(n^2) to build; key() has already ruled out duplicates.
        auto& members = static_cast<Json::object_t::Container&>(top.container->get_ref<Json::object_t&>());
        members.emplace_back(top.key, std::move(v));
        return &members.back().second;
    }

    bool value(Json&& v) {
        slot(std::move(v));
        return true;
    }

    bool open(Json&& container) {
        if (stack_.size() >= kMaxDepth)
            throw SceneError("", "malformed JSON: nested deeper than " + std::to_string(kMaxDepth) + " levels");
        // The parent's pointer stays valid: nothing is added to it until this one closes.
        stack_.push_back({slot(std::move(container)), {}, {}});
        return true;
    }

    bool close() {
        stack_.pop_back();
        return true;
    }

    // Path of the value being read; `key`, if given, replaces the innermost object key.
    std::string currentPath(const std::optional<std::string>& key) const {
        std::string path;
        for (size_t i = 0; i < stack_.size(); ++i) {
            const Frame& f = stack_[i];
            bool innermost = i + 1 == stack_.size();
            if (f.container->is_array()) {
                // Enclosing arrays already hold the element being read; the innermost one
                // has not received it yet.
                size_t n = f.container->size();
                path = elementPath(path, innermost ? n : n - 1);
            } else {
                path = childPath(path, innermost && key ? *key : f.key);
            }
        }
        return path;
    }

    std::vector<Frame> stack_;
};

std::string formatNumber(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

}  // namespace

Json parseJsonDocument(const std::string& text) {
    SceneSax sax;
    Json::sax_parse(text, &sax);  // errors are thrown from inside the handler
    return std::move(sax.root);
}

std::string childPath(const std::string& path, std::string_view key) {
    return path.empty() ? std::string(key) : path + "." + std::string(key);
}

std::string elementPath(const std::string& path, size_t index) {
    return path + "[" + std::to_string(index) + "]";
}

// ---- Range ----

bool Range::contains(double v) const {
    bool aboveLo = loOpen ? v > lo : v >= lo;
    bool belowHi = hiOpen ? v < hi : v <= hi;
    return aboveLo && belowHi;
}

std::string Range::describe() const {
    bool hasLo = std::isfinite(lo), hasHi = std::isfinite(hi);
    if (hasLo && !hasHi) return std::string("must be ") + (loOpen ? "> " : ">= ") + formatNumber(lo);
    if (!hasLo && hasHi) return std::string("must be ") + (hiOpen ? "< " : "<= ") + formatNumber(hi);
    return std::string("must be in ") + (loOpen ? "(" : "[") + formatNumber(lo) + ", " + formatNumber(hi) +
           (hiOpen ? ")" : "]");
}

// ---- JsonValue ----

void JsonValue::fail(const std::string& message) const { throw SceneError(path_, message); }

float JsonValue::number(const Range& range) const {
    if (!json_->is_number()) fail("must be a number");
    double v = json_->get<double>();
    // Finite as a float: the engine stores floats, and 1e300 would become inf there.
    if (!std::isfinite(v) || std::fabs(v) > std::numeric_limits<float>::max()) fail("must be a finite number");
    if (!range.contains(v)) fail(range.describe());
    return static_cast<float>(v);
}

int64_t JsonValue::integer(int64_t lo, int64_t hi) const {
    std::string expected = hi == std::numeric_limits<int64_t>::max()
                               ? "must be an integer >= " + std::to_string(lo)
                               : "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (json_->is_number_integer()) {  // also true for unsigned
        if (json_->is_number_unsigned() && json_->get<uint64_t>() > uint64_t(std::numeric_limits<int64_t>::max()))
            fail(expected);
        int64_t v = json_->get<int64_t>();
        if (v < lo || v > hi) fail(expected);
        return v;
    }
    if (!json_->is_number()) fail("must be a number");
    double d = json_->get<double>();
    // The bounds compare as doubles; |d| < 2^63 keeps the cast defined.
    if (!std::isfinite(d) || d != std::floor(d) || std::fabs(d) >= 9.2e18) fail(expected);
    auto v = static_cast<int64_t>(d);
    if (v < lo || v > hi) fail(expected);
    return v;
}

uint64_t JsonValue::unsignedInteger() const {
    const char* expected = "must be an integer >= 0";
    if (json_->is_number_unsigned()) return json_->get<uint64_t>();
    if (json_->is_number_integer()) fail(expected);  // signed means negative here
    if (!json_->is_number()) fail("must be a number");
    double d = json_->get<double>();
    if (!std::isfinite(d) || d != std::floor(d) || d < 0 || d >= 18446744073709551616.0) fail(expected);
    return static_cast<uint64_t>(d);
}

bool JsonValue::boolean() const {
    if (!json_->is_boolean()) fail("must be true or false");
    return json_->get<bool>();
}

const std::string& JsonValue::string() const {
    if (!json_->is_string()) fail("must be a string");
    return json_->get_ref<const std::string&>();
}

size_t JsonValue::choice(std::initializer_list<std::string_view> names, std::string_view what) const {
    const std::string& s = string();
    std::string list;
    size_t i = 0;
    for (std::string_view n : names) {
        if (s == n) return i;
        list += (i++ ? ", " : "") + std::string(n);
    }
    fail("unknown " + std::string(what) + " \"" + s + "\" (expected one of " + list + ")");
}

Vec3 JsonValue::vec3(const Range& range) const {
    if (!json_->is_array() || json_->size() != 3) fail("must be an array of 3 numbers");
    Vec3 v;
    for (int i = 0; i < 3; ++i) v[i] = JsonValue((*json_)[size_t(i)], elementPath(path_, i)).number(range);
    return v;
}

Vec2 JsonValue::vec2(const Range& range) const {
    if (!json_->is_array() || json_->size() != 2) fail("must be an array of 2 numbers");
    return {JsonValue((*json_)[0], elementPath(path_, 0)).number(range),
            JsonValue((*json_)[1], elementPath(path_, 1)).number(range)};
}

Vec3 JsonValue::direction() const {
    Vec3 v = vec3();
    // In double: squaring tiny but non-zero components in float would underflow to 0.
    double x = v.x, y = v.y, z = v.z, len = std::sqrt(x * x + y * y + z * z);
    if (len == 0) fail("must not be the zero vector");
    return Vec3(float(x / len), float(y / len), float(z / len));
}

std::vector<JsonValue> JsonValue::elements() const {
    if (!json_->is_array()) fail("must be an array");
    std::vector<JsonValue> out;
    out.reserve(json_->size());
    for (size_t i = 0; i < json_->size(); ++i) out.emplace_back((*json_)[i], elementPath(path_, i));
    return out;
}

JsonObject JsonValue::object() const {
    if (!json_->is_object()) fail("must be an object");
    return JsonObject(*json_, path_);
}

// ---- JsonObject ----

void JsonObject::fail(const std::string& message) const { throw SceneError(path_, message); }

bool JsonObject::has(std::string_view key) const { return json_->contains(key); }

std::optional<JsonValue> JsonObject::optional(std::string_view key) {
    auto it = json_->find(key);
    if (it == json_->end()) return std::nullopt;
    read_.emplace(key);
    return JsonValue(*it, childPath(path_, key));
}

namespace {

// Optimal string alignment distance (Levenshtein plus swaps of neighbours: "raduis" is one
// step from "radius"), case-insensitive.
size_t editDistance(std::string_view a, std::string_view b) {
    auto lower = [](char c) { return char(std::tolower(static_cast<unsigned char>(c))); };
    std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
    for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (size_t i = 1; i <= a.size(); ++i)
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) && lower(a[i - 2]) == lower(b[j - 1]))
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

}  // namespace

JsonValue JsonObject::required(std::string_view key) {
    auto v = optional(key);
    if (v) return *v;
    // A field not read (yet) that is a near miss of the one wanted is most likely it,
    // misspelt: say so, since the "unknown field" error it would cause comes only later.
    std::string nearest;
    size_t best = std::max<size_t>(1, key.size() / 3) + 1;
    for (auto it = json_->begin(); it != json_->end(); ++it)
        if (!read_.contains(it.key()))
            if (size_t d = editDistance(it.key(), key); d < best) best = d, nearest = it.key();
    if (nearest.empty()) throw SceneError(childPath(path_, key), "missing required field");
    throw SceneError(childPath(path_, key), "missing required field; found \"" + nearest +
                                                "\", which is not a field here: a misspelling of \"" +
                                                std::string(key) + "\"?");
}

std::vector<std::pair<std::string, JsonValue>> JsonObject::members() {
    std::vector<std::pair<std::string, JsonValue>> out;
    for (auto it = json_->begin(); it != json_->end(); ++it) {
        read_.insert(it.key());
        out.emplace_back(it.key(), JsonValue(it.value(), childPath(path_, it.key())));
    }
    return out;
}

void JsonObject::finish() const {
    for (auto it = json_->begin(); it != json_->end(); ++it)
        if (!read_.contains(it.key())) throw SceneError(childPath(path_, it.key()), "unknown field");
}

float JsonObject::number(std::string_view key, float fallback, const Range& range) {
    auto v = optional(key);
    return v ? v->number(range) : fallback;
}

int64_t JsonObject::integer(std::string_view key, int64_t fallback, int64_t lo, int64_t hi) {
    auto v = optional(key);
    return v ? v->integer(lo, hi) : fallback;
}

bool JsonObject::boolean(std::string_view key, bool fallback) {
    auto v = optional(key);
    return v ? v->boolean() : fallback;
}

Vec3 JsonObject::vec3(std::string_view key, Vec3 fallback, const Range& range) {
    auto v = optional(key);
    return v ? v->vec3(range) : fallback;
}

size_t JsonObject::choice(std::string_view key, size_t fallback, std::initializer_list<std::string_view> names,
                          std::string_view what) {
    auto v = optional(key);
    return v ? v->choice(names, what) : fallback;
}

}  // namespace photon
