#include "api/errors.h"
#include <httplib.h>
#include <spdlog/spdlog.h>
#include <nlohmann/json.hpp>

namespace photon::api {

namespace {

struct KindInfo {
    const char* name;
    const char* title;
};

KindInfo kindInfo(server::ErrorKind kind) {
    switch (kind) {
        case server::ErrorKind::BadRequest: return {"bad-request", "Bad request"};
        case server::ErrorKind::NotFound: return {"not-found", "Not found"};
        case server::ErrorKind::NotReady: return {"not-ready", "Not ready yet"};
        case server::ErrorKind::Conflict: return {"conflict", "Not possible in the job's state"};
        case server::ErrorKind::PayloadTooLarge: return {"payload-too-large", "Upload too large"};
        case server::ErrorKind::LimitExceeded: return {"limit-exceeded", "Over a server limit"};
        case server::ErrorKind::Unavailable: return {"unavailable", "Server at capacity"};
        case server::ErrorKind::TooManyRequests: return {"too-many-requests", "Over this client's share"};
        case server::ErrorKind::StorageFull: return {"storage-full", "Disk full"};
    }
    return {"internal", "Internal error"};
}

constexpr const char* kTypePrefix = "urn:photon:problem:";

}  // namespace

const char* reasonPhrase(int status) {
    switch (status) {
        case 400: return "Bad Request";
        case 401: return "Unauthorized";
        case 403: return "Forbidden";
        case 404: return "Not Found";
        case 405: return "Method Not Allowed";
        case 408: return "Request Timeout";
        case 409: return "Conflict";
        case 413: return "Payload Too Large";
        case 414: return "URI Too Long";
        case 415: return "Unsupported Media Type";
        case 416: return "Range Not Satisfiable";
        case 421: return "Misdirected Request";
        case 422: return "Unprocessable Entity";
        case 429: return "Too Many Requests";
        case 431: return "Request Header Fields Too Large";
        case 503: return "Service Unavailable";
        case 507: return "Insufficient Storage";
        default: return status >= 500 ? "Internal Server Error" : "Error";
    }
}

int statusFor(server::ErrorKind kind) {
    switch (kind) {
        case server::ErrorKind::BadRequest: return 400;
        case server::ErrorKind::NotFound: return 404;
        case server::ErrorKind::NotReady: return 404;
        case server::ErrorKind::Conflict: return 409;
        case server::ErrorKind::PayloadTooLarge: return 413;
        case server::ErrorKind::LimitExceeded: return 422;
        case server::ErrorKind::Unavailable: return 503;
        case server::ErrorKind::TooManyRequests: return 429;
        case server::ErrorKind::StorageFull: return 507;
    }
    return 500;
}

Problem problemFor(const server::ServiceError& error) {
    Problem problem{statusFor(error.kind()), error.what()};
    KindInfo info = kindInfo(error.kind());
    problem.type = std::string(kTypePrefix) + info.name;
    problem.title = info.title;
    if (error.scenePath()) {
        problem.type = std::string(kTypePrefix) + "scene-invalid";
        problem.title = "Invalid scene";
        problem.scenePath = error.scenePath();
        problem.scenePathIsJson = error.scenePathIsJson();
    }
    return problem;
}

std::string jsonPointerOf(const std::string& path) {
    std::string pointer;
    std::string name;
    auto flush = [&] {
        pointer += '/';
        for (char c : name) pointer += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
        name.clear();
    };
    bool pending = false;
    for (size_t i = 0; i < path.size(); ++i) {
        char c = path[i];
        if (c == '.') {
            if (pending) flush();
            pending = false;
        } else if (c == '[') {
            if (pending) flush();
            size_t end = path.find(']', i);
            if (end == std::string::npos) end = path.size();
            name = path.substr(i + 1, end - i - 1);
            flush();
            pending = false;
            i = end;
        } else {
            name += c;
            pending = true;
        }
    }
    if (pending) flush();
    return pointer;
}

std::string problemBody(const Problem& problem) {
    nlohmann::json body{{"type", problem.type},
                        {"title", problem.title.empty() ? std::string(reasonPhrase(problem.status)) : problem.title},
                        {"status", problem.status},
                        {"detail", problem.detail},
                        {"error", problem.detail}};
    if (problem.scenePath) {
        body["path"] = *problem.scenePath;
        if (problem.scenePathIsJson) body["pointer"] = jsonPointerOf(*problem.scenePath);
    }
    // Replace: the message may not be valid UTF-8 (it can quote client input).
    return body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

void sendProblem(httplib::Response& res, const Problem& problem) {
    res.status = problem.status;
    res.set_content(problemBody(problem), kProblemJson);
}

void sendError(httplib::Response& res, int status, const std::string& message,
               const std::optional<std::string>& path) {
    if (path) return sendProblem(res, problemFor(server::ServiceError(server::ErrorKind::BadRequest, message, path)));
    sendProblem(res, {status, message});
}

void sendException(httplib::Response& res, std::exception_ptr error) {
    try {
        std::rethrow_exception(error);
    } catch (const server::ServiceError& e) {
        int status = statusFor(e.kind());
        // Capacity answers, and "not yet", say when to try again (RFC 9110 section 10.2.3).
        if (status == 429 || status == 503 || e.kind() == server::ErrorKind::NotReady)
            res.set_header("Retry-After", std::to_string(kRetryAfterSeconds));
        sendProblem(res, problemFor(e));
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
