// Query-string parameters, checked: a bad value is a 400 naming the parameter.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace httplib {
struct Request;
}

namespace photon::api {

std::optional<int64_t> integerParam(const httplib::Request& req, const std::string& name, int64_t lo, int64_t hi);
std::optional<uint64_t> unsignedParam(const httplib::Request& req, const std::string& name);
std::optional<std::string> stringParam(const httplib::Request& req, const std::string& name);
// The {id} of a /api/v1/jobs/{id}... route (its single capture group).
std::string pathId(const httplib::Request& req);

}  // namespace photon::api
