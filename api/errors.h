// HTTP error responses: the JSON body {"error": "...", "path": "..."} and the mapping from
// service error kinds (and anything unexpected) to status codes.
#pragma once
#include <exception>
#include <optional>
#include <string>
#include "server/errors.h"

namespace httplib {
struct Response;
}

namespace photon::api {

int statusFor(server::ErrorKind kind);

// `path` is the scene's JSON path for scene errors; omitted otherwise.
void sendError(httplib::Response& res, int status, const std::string& message,
               const std::optional<std::string>& path = std::nullopt);

// Answers for the exception in flight or in `error`: ServiceError by its kind, malformed
// JSON as 400, anything else as 500 without internals.
void sendException(httplib::Response& res, std::exception_ptr error);

[[noreturn]] void throwBadRequest(const std::string& message);

}  // namespace photon::api
