#include "api/params.h"
#include <algorithm>
#include <httplib.h>
#include <sstream>
#include "api/errors.h"

namespace photon::api {

std::vector<std::string> stringParams(const httplib::Request& req, const std::string& name) {
    std::vector<std::string> values;
    size_t count = req.get_param_value_count(name);
    for (size_t i = 0; i < count; ++i) {
        std::string value = req.get_param_value(name, i);
        for (size_t start = 0; start <= value.size();) {
            size_t comma = std::min(value.find(',', start), value.size());
            values.push_back(value.substr(start, comma - start));
            start = comma + 1;
        }
    }
    return values;
}

std::optional<std::string> stringParam(const httplib::Request& req, const std::string& name) {
    if (!req.has_param(name)) return std::nullopt;
    if (req.get_param_value_count(name) > 1) throwBadRequest("query parameter " + name + " given more than once");
    return req.get_param_value(name);
}

std::optional<bool> booleanParam(const httplib::Request& req, const std::string& name) {
    std::optional<std::string> text = stringParam(req, name);
    if (!text) return std::nullopt;
    if (*text != "true" && *text != "false") throwBadRequest("query parameter " + name + ": must be true or false");
    return *text == "true";
}

std::optional<int64_t> integerParam(const httplib::Request& req, const std::string& name, int64_t lo, int64_t hi) {
    std::optional<std::string> text = stringParam(req, name);
    if (!text) return std::nullopt;
    std::optional<int64_t> value = parseWhole<int64_t>(*text);
    if (!value || *value < lo || *value > hi)
        throwBadRequest("query parameter " + name + ": expected an integer in [" + std::to_string(lo) + ", " +
                        std::to_string(hi) + "]");
    return value;
}

std::optional<uint64_t> unsignedParam(const httplib::Request& req, const std::string& name) {
    std::optional<std::string> text = stringParam(req, name);
    if (!text) return std::nullopt;
    std::optional<uint64_t> value = parseWhole<uint64_t>(*text);
    if (!value) throwBadRequest("query parameter " + name + ": expected an integer in [0, 2^64-1]");
    return value;
}

std::optional<double> numberParam(const httplib::Request& req, const std::string& name, double lo, double hi) {
    std::optional<std::string> text = stringParam(req, name);
    if (!text) return std::nullopt;
    double value = 0;
    auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), value);
    // from_chars also reads "inf" and "nan"; the range check refuses both.
    if (ec != std::errc() || end != text->data() + text->size() || text->empty() || !(value >= lo && value <= hi)) {
        std::ostringstream range;
        range << "[" << lo << ", " << hi << "]";
        throwBadRequest("query parameter " + name + ": expected a number in " + range.str());
    }
    return value;
}

std::string pathId(const httplib::Request& req) { return req.matches.size() > 1 ? req.matches[1].str() : ""; }

}  // namespace photon::api
