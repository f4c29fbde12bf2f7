// HTTP error responses as RFC 9457 problem details (application/problem+json):
//   {"type": URI, "title": ..., "status": N, "detail": what went wrong,
//    "error": the same as detail (what clients of earlier versions read),
//    "path": "shapes[2].file", "pointer": "/shapes/2/file"}   (scene errors only)
// and the mapping from service error kinds (and anything unexpected) to status and type.
#pragma once
#include <exception>
#include <optional>
#include <string>
#include "server/errors.h"

namespace httplib {
struct Response;
}

namespace photon::api {

inline constexpr const char* kProblemJson = "application/problem+json";

// Retry-After of capacity answers (429, 503) and of "not ready yet": a limit frees up when a
// job finishes or a stream ends, an image comes with the first pass: seconds, not minutes.
inline constexpr int kRetryAfterSeconds = 5;

struct Problem {
    Problem(int status, std::string detail) : status(status), detail(std::move(detail)) {}

    int status;
    std::string detail;
    // "urn:photon:problem:<name>" for the service's own kinds (see errorKindName), else
    // "about:blank" (the status says it all; the title is its reason phrase).
    std::string type = "about:blank";
    std::optional<std::string> scenePath;  // the scene's JSON path, for scene errors
    bool scenePathIsJson = true;           // false: an imported file's place, with no JSON Pointer
    std::string title;                     // empty: the status's reason phrase
};

// The reason phrase of an HTTP status (RFC 9110 section 15), for status lines and titles.
const char* reasonPhrase(int status);

int statusFor(server::ErrorKind kind);
// The problem a service error is: its status, and its type by kind: scene-invalid (a bad
// request with a scene path), bad-request, not-found, not-ready, conflict,
// payload-too-large, limit-exceeded, unavailable, too-many-requests, storage-full.
Problem problemFor(const server::ServiceError& error);
// "shapes[2].file" -> "/shapes/2/file" (RFC 6901, with ~ and / escaped in names).
std::string jsonPointerOf(const std::string& scenePath);

std::string problemBody(const Problem& problem);
void sendProblem(httplib::Response& res, const Problem& problem);
// A problem of type about:blank (or scene-invalid when `path` is given).
void sendError(httplib::Response& res, int status, const std::string& message,
               const std::optional<std::string>& path = std::nullopt);

// Answers for the exception in flight or in `error`: ServiceError by its kind, malformed
// JSON as 400, anything else as 500 without internals.
void sendException(httplib::Response& res, std::exception_ptr error);

[[noreturn]] void throwBadRequest(const std::string& message);

}  // namespace photon::api
