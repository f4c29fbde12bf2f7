// The HTTP front: the connection guard on the TCP port (connection_guard.h) before an
// httplib::Server on a private Unix socket, with the route table registered, bearer-token
// auth, JSON errors for everything (unknown routes, oversized bodies, exceptions), request
// metrics, and static files from the web root when it exists.
#pragma once
#include <httplib.h>
#include <memory>
#include <string>
#include <vector>
#include "api/connection_guard.h"
#include "api/request_origin.h"
#include "api/routes.h"
#include "api/sessions.h"
#include "api/stream_support.h"

namespace photon::api {

struct HttpConfig {
    std::string token;    // empty: no authentication
    std::string webRoot;  // served at "/" if the folder exists
    size_t maxBodyBytes = 0;
    int maxStreams = 48;  // open event and image streams; each holds an HTTP thread
    std::vector<std::string> allowedHosts;    // see OriginPolicy
    std::vector<std::string> allowedOrigins;
    GuardLimits connections;
};

class HttpServer {
public:
    HttpServer(server::JobService& service, const HttpConfig& config);
    ~HttpServer();

    // Binds; port 0 picks a free port. Returns the bound port, or -1 on failure.
    int bind(const std::string& host, int port);
    // Serves until stop(); blocks.
    bool listen();
    void stop();
    // See StreamSlots::waitUntilWritten.
    bool waitForStreams(std::chrono::milliseconds timeout) { return streams_.waitUntilWritten(timeout); }
    bool running() const { return server_.is_running() && guard_.running(); }

private:
    void configure(const HttpConfig& config);
    bool authorized(const httplib::Request& req) const;

    StreamSlots streams_;
    RouteContext context_;
    OriginPolicy origin_;  // the bound address and port are filled in by bind()
    std::string token_;
    mutable SessionStore sessions_;  // valid() drops expired sessions
    std::string socketFolder_;  // private (0700), holds httplib's Unix socket
    httplib::Server server_;
    ConnectionGuard guard_;
};

}  // namespace photon::api
