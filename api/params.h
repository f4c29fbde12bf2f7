// Query-string parameters, checked: a bad value is a 400 naming the parameter.
#pragma once
#include <charconv>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace httplib {
struct Request;
}

namespace photon::api {

// A whole decimal number of type T (int64_t, uint64_t): no sign for unsigned, no spaces,
// nothing after it; nothing for an empty or out-of-range text.
template <typename T>
std::optional<T> parseWhole(const std::string& text) {
    T value{};
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
    return value;
}

std::optional<int64_t> integerParam(const httplib::Request& req, const std::string& name, int64_t lo, int64_t hi);
std::optional<uint64_t> unsignedParam(const httplib::Request& req, const std::string& name);
// A finite decimal number (e.g. "1.5", "-2", "2e-1") in [lo, hi].
std::optional<double> numberParam(const httplib::Request& req, const std::string& name, double lo, double hi);
std::optional<std::string> stringParam(const httplib::Request& req, const std::string& name);
// "true" or "false"; anything else is a 400 naming the parameter.
std::optional<bool> booleanParam(const httplib::Request& req, const std::string& name);
// Every value of a parameter that may be repeated ("label=a&label=b"), in order; a value
// holding commas counts as that many ("status=queued,running").
std::vector<std::string> stringParams(const httplib::Request& req, const std::string& name);
// The {id} of a /api/v1/jobs/{id}... route (its single capture group).
std::string pathId(const httplib::Request& req);

}  // namespace photon::api
