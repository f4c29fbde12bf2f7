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

// Retry-After of capacity answers (429, 503): a limit frees up when a job finishes or a
// stream ends, in seconds, not minutes.
inline constexpr int kRetryAfterSeconds = 5;

int statusFor(server::ErrorKind kind);

// The JSON body of every error: {"error": message, "path": path}; `path` is the scene's JSON
// path for scene errors, omitted otherwise.
std::string errorBody(const std::string& message, const std::optional<std::string>& path = std::nullopt);

void sendError(httplib::Response& res, int status, const std::string& message,
               const std::optional<std::string>& path = std::nullopt);

// Answers for the exception in flight or in `error`: ServiceError by its kind, malformed
// JSON as 400, anything else as 500 without internals.
void sendException(httplib::Response& res, std::exception_ptr error);

[[noreturn]] void throwBadRequest(const std::string& message);

}  // namespace photon::api
