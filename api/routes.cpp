#include "api/routes.h"
#include <httplib.h>
#include <array>
#include <regex>
#include "api/errors.h"
#include "api/handlers.h"

namespace photon::api {

namespace {

constexpr std::array<Route, 24> kRoutes{{
    {"GET", "/", homePage, nullptr},
    {"GET", "/metrics", metrics, nullptr},
    {"GET", "/api/v1/health", health, nullptr},
    {"GET", "/api/v1/info", info, nullptr},
    {"GET", "/api/v1/workers", listWorkers, nullptr},
    {"POST", "/api/v1/session", startSession, nullptr},
    {"DELETE", "/api/v1/session", endSession, nullptr},
    {"GET", "/api/v1/events", serviceEvents, nullptr},
    {"GET", "/api/v1/jobs", listJobs, nullptr},
    {"POST", "/api/v1/jobs", nullptr, createJob},
    {"GET", "/api/v1/jobs/{id}", getJob, nullptr},
    {"DELETE", "/api/v1/jobs/{id}", deleteJob, nullptr},
    {"PATCH", "/api/v1/jobs/{id}", updateJob, nullptr},
    {"POST", "/api/v1/jobs/{id}/clone", cloneJob, nullptr},
    {"POST", "/api/v1/jobs/{id}/pause", pauseJob, nullptr},
    {"POST", "/api/v1/jobs/{id}/resume", resumeJob, nullptr},
    {"POST", "/api/v1/jobs/{id}/continue", continueJob, nullptr},
    {"GET", "/api/v1/jobs/{id}/scene", getScene, nullptr},
    {"GET", "/api/v1/jobs/{id}/log", getLog, nullptr},
    {"GET", "/api/v1/jobs/{id}/progress", getProgressHistory, nullptr},
    {"POST", "/api/v1/jobs/{id}/cancel", cancelJob, nullptr},
    {"GET", "/api/v1/jobs/{id}/image", getImage, nullptr},
    {"GET", "/api/v1/jobs/{id}/events", jobEvents, nullptr},
    {"GET", "/api/v1/jobs/{id}/stream", streamImages, nullptr},
}};

// "/api/v1/jobs/{id}" -> "/api/v1/jobs/([^/]+)"; the templates contain no other regex syntax.
std::string toRegex(const std::string& path) {
    return std::regex_replace(path, std::regex(R"(\{[a-z_]+\})"), "([^/]+)");
}

// A body-reading handler also needs a plain registration: httplib only offers the content
// reader when a request has a body, and an empty POST must still reach the handler (which
// then reports the empty body).
httplib::ContentReader readerOver(const std::string& body) {
    return httplib::ContentReader(
        [&body](httplib::ContentReceiver receive) { return body.empty() || receive(body.data(), body.size()); },
        [](httplib::MultipartContentHeader, httplib::ContentReceiver) { return false; });
}

template <typename Fn>
void guarded(httplib::Response& res, Fn&& fn) {
    try {
        fn();
    } catch (...) {
        sendException(res, std::current_exception());
    }
}

void registerOne(httplib::Server& server, RouteContext& context, const Route& route) {
    const std::string pattern = toRegex(route.path);
    const std::string method = route.method;
    if (route.bodyHandler) {
        BodyHandler h = route.bodyHandler;
        auto withReader = [&context, h](const httplib::Request& req, httplib::Response& res,
                                        const httplib::ContentReader& reader) {
            guarded(res, [&] { h(context, req, res, reader); });
        };
        auto withoutBody = [&context, h](const httplib::Request& req, httplib::Response& res) {
            guarded(res, [&] { h(context, req, res, readerOver(req.body)); });
        };
        if (method == "POST") server.Post(pattern, withReader).Post(pattern, withoutBody);
        return;
    }
    Handler h = route.handler;
    auto plain = [&context, h](const httplib::Request& req, httplib::Response& res) {
        guarded(res, [&] { h(context, req, res); });
    };
    if (method == "GET") server.Get(pattern, plain);
    else if (method == "POST") server.Post(pattern, plain);
    else if (method == "DELETE") server.Delete(pattern, plain);
    else if (method == "PATCH") server.Patch(pattern, plain);
}

}  // namespace

std::span<const Route> routeTable() { return kRoutes; }

void registerRoutes(httplib::Server& server, RouteContext& context) {
    for (const Route& route : kRoutes) registerOne(server, context, route);
}

namespace {
// The routes' patterns, compiled once: the table is fixed for the life of the process.
const std::vector<std::regex>& routePatterns() {
    static const std::vector<std::regex> patterns = [] {
        std::vector<std::regex> out;
        for (const Route& r : kRoutes) out.emplace_back(toRegex(r.path));
        return out;
    }();
    return patterns;
}
}  // namespace

std::string routeLabel(const std::string& method, const std::string& path) {
    for (size_t i = 0; i < kRoutes.size(); ++i)
        if ((method == kRoutes[i].method || (method == "HEAD" && std::string(kRoutes[i].method) == "GET")) &&
            std::regex_match(path, routePatterns()[i]))
            return kRoutes[i].path;
    return "unmatched";
}

std::string allowedMethods(const std::string& path) {
    std::string allowed;
    for (size_t i = 0; i < kRoutes.size(); ++i)
        if (std::regex_match(path, routePatterns()[i]))
            allowed += (allowed.empty() ? "" : ", ") + std::string(kRoutes[i].method);
    return allowed;
}

}  // namespace photon::api
