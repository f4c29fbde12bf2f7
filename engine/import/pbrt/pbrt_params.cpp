#include "import/pbrt/pbrt_params.h"
#include <algorithm>
#include <photon/errors.h>

namespace photon::pbrt {

std::string describe(const Directive& d) {
    std::string s = d.name;
    if (!d.strings.empty()) s += " \"" + d.strings.front() + "\"";
    return s;
}

void fail(const Location& where, const std::string& message) { throw SceneError(where.str(), message); }

const Param* Params::find(std::string_view name) const {
    const Param* p = d_.find(name);
    if (p) p->used = true;
    return p;
}

const Param& Params::checked(const Param& p, std::initializer_list<std::string_view> types, size_t count) const {
    if (std::find(types.begin(), types.end(), p.type) == types.end()) {
        std::string expected;
        for (std::string_view t : types) expected += (expected.empty() ? "" : " or ") + std::string(t);
        fail(p.where, describe(d_) + ": parameter \"" + p.name + "\" must be " + expected + ", not " + p.type);
    }
    const size_t n = p.numbers.size() + p.strings.size() + p.bools.size();
    if (count && n != count)
        fail(p.where, describe(d_) + ": parameter \"" + p.name + "\" needs " + std::to_string(count) +
                          (count == 1 ? " value" : " values") + ", not " + std::to_string(n));
    return p;
}

std::optional<double> Params::number(std::string_view name) const {
    const Param* p = find(name);
    if (!p) return std::nullopt;
    return checked(*p, {"float", "integer"}, 1).numbers.at(0);
}

double Params::number(std::string_view name, double fallback) const { return number(name).value_or(fallback); }

bool Params::boolean(std::string_view name, bool fallback) const {
    const Param* p = find(name);
    if (!p) return fallback;
    const Param& c = checked(*p, {"bool"}, 1);
    if (c.bools.empty()) fail(p->where, describe(d_) + ": parameter \"" + p->name + "\" must be true or false");
    return c.bools[0];
}

std::optional<std::string> Params::string(std::string_view name) const {
    const Param* p = find(name);
    if (!p) return std::nullopt;
    const Param& c = checked(*p, {"string", "texture"}, 1);
    if (c.strings.empty()) fail(p->where, describe(d_) + ": parameter \"" + p->name + "\" must be a string");
    return c.strings[0];
}

std::string Params::string(std::string_view name, const std::string& fallback) const {
    return string(name).value_or(fallback);
}

std::vector<double> Params::numbers(std::string_view name, std::initializer_list<std::string_view> types) const {
    const Param* p = find(name);
    if (!p) return {};
    const Param& c = checked(*p, types, 0);
    if (!c.strings.empty() || !c.bools.empty())
        fail(p->where, describe(d_) + ": parameter \"" + p->name + "\" must hold numbers");
    return c.numbers;
}

std::vector<std::string> Params::strings(std::string_view name) const {
    const Param* p = find(name);
    if (!p) return {};
    return checked(*p, {"string"}, 0).strings;
}

Vec3 Params::vec3(std::string_view name, Vec3 fallback) const {
    const Param* p = find(name);
    if (!p) return fallback;
    const Param& c = checked(*p, {"point3", "point", "vector3", "vector", "normal", "normal3"}, 3);
    return {float(c.numbers.at(0)), float(c.numbers.at(1)), float(c.numbers.at(2))};
}

void Params::markAllRead() const {
    for (const Param& p : d_.params) p.used = true;
}

void Params::warnUnused(std::vector<std::string>& warnings) const {
    for (const Param& p : d_.params)
        if (!p.used)
            warnings.push_back(p.where.str() + ": " + describe(d_) + ": parameter \"" + p.name + "\" (" + p.type +
                               ") ignored");
}

}  // namespace photon::pbrt
