#include "api/errors.h"
#include <httplib.h>
#include <spdlog/spdlog.h>
#include <nlohmann/json.hpp>

namespace photon::api {

int statusFor(server::ErrorKind kind) {
    switch (kind) {
        case server::ErrorKind::BadRequest: return 400;
        case server::ErrorKind::NotFound: return 404;
        case server::ErrorKind::Conflict: return 409;
        case server::ErrorKind::PayloadTooLarge: return 413;
        case server::ErrorKind::LimitExceeded: return 422;
        case server::ErrorKind::Unavailable: return 503;
        case server::ErrorKind::TooManyRequests: return 429;
        case server::ErrorKind::StorageFull: return 507;
    }
    return 500;
}

std::string errorBody(const std::string& message, const std::optional<std::string>& path) {
    nlohmann::json body{{"error", message}};
    if (path) body["path"] = *path;
    // Replace: the message may not be valid UTF-8 (it can quote client input).
    return body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

void sendError(httplib::Response& res, int status, const std::string& message,
               const std::optional<std::string>& path) {
    res.status = status;
    res.set_content(errorBody(message, path), "application/json");
}

void sendException(httplib::Response& res, std::exception_ptr error) {
    try {
        std::rethrow_exception(error);
    } catch (const server::ServiceError& e) {
        int status = statusFor(e.kind());
        // Capacity answers say when to try again (RFC 9110 section 10.2.3).
        if (status == 429 || status == 503) res.set_header("Retry-After", std::to_string(kRetryAfterSeconds));
        sendError(res, status, e.what(), e.scenePath());
    } catch (const nlohmann::json::exception& e) {
        sendError(res, 400, std::string("malformed JSON: ") + e.what());
    } catch (const std::exception& e) {
        spdlog::error("internal error: {}", e.what());
        sendError(res, 500, "internal server error");
    } catch (...) {
        spdlog::error("internal error of unknown type");
        sendError(res, 500, "internal server error");
    }
}

void throwBadRequest(const std::string& message) {
    throw server::ServiceError(server::ErrorKind::BadRequest, message);
}

}  // namespace photon::api
