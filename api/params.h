// Query-string parameters, checked: a bad value is a 400 naming the parameter.
#pragma once
#include <charconv>
#include <cstdint>
#include <optional>
#include <string>

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
std::optional<std::string> stringParam(const httplib::Request& req, const std::string& name);
// The {id} of a /api/v1/jobs/{id}... route (its single capture group).
std::string pathId(const httplib::Request& req);

}  // namespace photon::api
