// The one table of HTTP routes. Registration with httplib, the --print-routes listing, the
// per-route request metrics and the OpenAPI consistency test all read it, so a route cannot
// exist in one place and be missing in another.
#pragma once
#include <span>
#include <string>
#include "server/job_service.h"

namespace httplib {
class Server;
class ContentReader;
struct Request;
struct Response;
}  // namespace httplib

namespace photon::api {

class StreamSlots;
class SessionStore;

struct RouteContext {
    server::JobService& service;
    StreamSlots& streams;     // caps the long-lived event and image streams
    SessionStore& sessions;   // browser sessions (sessions.h)
    bool tokenRequired;       // the server runs with a token
};

using Handler = void (*)(RouteContext&, const httplib::Request&, httplib::Response&);
// Handlers that read the body themselves (streamed uploads).
using BodyHandler = void (*)(RouteContext&, const httplib::Request&, httplib::Response&,
                             const httplib::ContentReader&);

struct Route {
    const char* method;  // "GET", "POST", "PATCH", "DELETE"
    const char* path;    // OpenAPI template, e.g. "/api/v1/jobs/{id}"; {id} is req.matches[1]
    Handler handler;          // exactly one of handler and bodyHandler is set
    BodyHandler bodyHandler;
};

std::span<const Route> routeTable();

// Registers every route; each handler runs under a catch-all that turns exceptions into
// JSON error responses.
void registerRoutes(httplib::Server& server, RouteContext& context);

// The route template a request matched, or "unmatched": a bounded label for metrics.
std::string routeLabel(const std::string& method, const std::string& path);
// The methods the routes at `path` take, as an Allow header lists them ("GET, DELETE"), or
// "" when no route has that path.
std::string allowedMethods(const std::string& path);

}  // namespace photon::api
