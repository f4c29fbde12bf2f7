// Typed reading of a pbrt directive's parameters ("float fov" [45], "rgb L" [1 1 1], ...),
// marking each one read so that what the importer left unread becomes a warning.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>
#include <photon/vec.h>
#include "import/pbrt/pbrt_parser.h"

namespace photon::pbrt {

// What a directive was, for messages: `Shape "trianglemesh" at scene.pbrt:12`.
std::string describe(const Directive& d);

// A SceneError at the directive's or parameter's file:line.
[[noreturn]] void fail(const Location& where, const std::string& message);

class Params {
public:
    explicit Params(const Directive& d) : d_(d) {}
    const Directive& directive() const { return d_; }

    // The parameter, marked read; null if absent.
    const Param* find(std::string_view name) const;
    bool has(std::string_view name) const { return d_.find(name) != nullptr; }

    // One number ("float", "integer"); the fallback if absent; an error if it has another type
    // or not exactly one value.
    double number(std::string_view name, double fallback) const;
    std::optional<double> number(std::string_view name) const;
    bool boolean(std::string_view name, bool fallback) const;
    std::string string(std::string_view name, const std::string& fallback) const;
    std::optional<std::string> string(std::string_view name) const;
    // All the numbers of a numeric parameter ("point3 P", "integer indices"), of one of `types`.
    std::vector<double> numbers(std::string_view name, std::initializer_list<std::string_view> types) const;
    std::vector<std::string> strings(std::string_view name) const;
    // A 3-vector parameter ("point3 from", "vector3 axis"); the fallback if absent.
    Vec3 vec3(std::string_view name, Vec3 fallback) const;

    // Warnings for the parameters nothing read: "scene.pbrt:12: Shape \"trianglemesh\": parameter
    // \"S\" (normal3) ignored".
    void warnUnused(std::vector<std::string>& warnings) const;
    // Marks every parameter read: for a directive left out as a whole.
    void markAllRead() const;

private:
    const Param& checked(const Param& p, std::initializer_list<std::string_view> types, size_t count) const;
    const Directive& d_;
};

}  // namespace photon::pbrt
