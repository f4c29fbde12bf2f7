#include "api/http_server.h"
#include <spdlog/spdlog.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>
#include <cstdlib>
#include <thread>
#include <cctype>
#include <filesystem>
#include "api/guard_fields.h"
#include "api/errors.h"
#include "api/request_framing.h"
#include "api/request_ranges.h"

namespace photon::api {

namespace {

// httplib serves a connection on one thread; the guard hands it one request at a time and
// closes its connection once answered, so a thread is held per request being answered, and
// per open event or image stream for as long as it lasts.
constexpr size_t kHttpThreads = 256;
static_assert(server::kMaxStreamsCap + 64 <= int(kHttpThreads), "streams must leave threads for requests");
// Request threads run at this nice value: when they compete with a render for the cores,
// the render keeps most of them (a request is short; a pass is what people wait for).
constexpr int kHttpNice = 5;

// httplib's pool whose threads lower their own priority before their first request (a
// Linux thread's nice value is its own: setpriority on its thread id).
class LowPriorityThreadPool final : public httplib::TaskQueue {
public:
    explicit LowPriorityThreadPool(size_t threads) : pool_(threads) {}
    void enqueue(std::function<void()> fn) override {
        pool_.enqueue([fn = std::move(fn)] {
            thread_local bool lowered = false;
            if (!lowered) {
                setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), kHttpNice);
                lowered = true;
            }
            fn();
        });
    }
    void shutdown() override { pool_.shutdown(); }

private:
    httplib::ThreadPool pool_;
};

const char* reasonFor(int status) {
    switch (status) {
        case 400: return "bad request";
        case 401: return "missing or wrong bearer token";
        case 404: return "no such route";
        case 405: return "method not allowed";
        case 413: return "request body too large";
        case 414: return "request URI too long";
        case 415: return "unsupported request body type";
        case 421: return "misdirected request";
        case 503: return "server busy";
        default: return status >= 500 ? "internal server error" : "request failed";
    }
}

// An answer before the request's body was read: the connection is closed after it, or the
// unread body would be taken for the next request on it (and that request never answered).
// httplib closes a connection after a response when the request asked for it.
void refuseUnread(const httplib::Request& req, httplib::Response& res, int status, const std::string& message) {
    sendError(res, status, message);
    auto& headers = const_cast<httplib::Request&>(req).headers;  // httplib's own request, not const
    headers.erase("Connection");
    headers.emplace("Connection", "close");
}

// The two changes made to a request, before httplib reads on or answers it:
//  - ranges it may not have are dropped (request_ranges.h), with the Range header itself
//    (httplib would answer a file 206 for the header alone);
//  - a request with neither Content-Length nor Transfer-Encoding has no body (RFC 9112 6.3),
//    which httplib would otherwise wait for until the connection closes (curl -X POST).
void adjustBeforeReading(httplib::Request& req) {
    std::vector<std::pair<long, long>> kept = rangesToHonour(req.path, {req.ranges.begin(), req.ranges.end()});
    req.ranges.assign(kept.begin(), kept.end());
    if (kept.empty()) req.headers.erase("Range");
    if (!req.has_header("Content-Length") && !req.has_header("Transfer-Encoding"))
        req.headers.emplace("Content-Length", "0");
}

// A folder only this user can enter, for httplib's socket: no other local user can reach the
// server past the guard.
std::string makeSocketFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "photon-http-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot make a folder for the HTTP socket in " + pattern);
    return pattern;
}

}  // namespace

HttpServer::HttpServer(server::JobService& service, const HttpConfig& config)
    : streams_(config.maxStreams),
      context_{service, streams_, sessions_, !config.token.empty()},
      origin_{"", 0, config.allowedHosts, config.allowedOrigins},
      token_(config.token),
      socketFolder_(makeSocketFolder()),
      guard_(config.connections, socketFolder_ + "/http.sock") {
    configure(config);
}

HttpServer::~HttpServer() {
    std::error_code ec;
    std::filesystem::remove_all(socketFolder_, ec);
}

bool HttpServer::listen() {
    std::thread guard([this] { guard_.run(); });
    bool ok = server_.listen_after_bind();
    guard_.stop();
    guard.join();
    return ok;
}

void HttpServer::stop() {
    server_.stop();
    guard_.stop();
}

bool HttpServer::authorized(const httplib::Request& req) const {
    // The page's static files carry no secrets and a browser cannot attach the token to
    // them; the page then asks for the token before it calls the API.
    bool isApi = req.path.rfind("/api/", 0) == 0 || req.path == "/metrics";
    if (token_.empty() || req.path == "/api/v1/health" || !isApi) return true;
    // What a browser fetches by itself (streams, images, links) carries the session cookie
    // the page got for its token (sessions.h).
    if (std::optional<std::string> session = SessionStore::idInCookies(req.get_header_value("Cookie")))
        if (sessions_.valid(*session)) return true;
    const std::string header = req.get_header_value("Authorization");
    const std::string scheme = "bearer ";
    if (header.size() < scheme.size()) return false;
    for (size_t i = 0; i < scheme.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(header[i])) != scheme[i]) return false;
    return constantTimeEquals(header.substr(scheme.size()), token_);
}

void HttpServer::configure(const HttpConfig& config) {
    server_.new_task_queue = [] { return new LowPriorityThreadPool(kHttpThreads); };
    server_.set_payload_max_length(config.maxBodyBytes);
    server_.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
        // How it is framed and where it comes from first: an ambiguous, forged or rebound
        // request is refused with or without a token, before its body is read.
        std::optional<Refusal> refusal = checkRequestPath(req);
        if (!refusal) refusal = checkRequestOrigin(req, origin_);
        if (refusal) {
            refuseUnread(req, res, refusal->status, refusal->message);
            return httplib::Server::HandlerResponse::Handled;
        }
        adjustBeforeReading(const_cast<httplib::Request&>(req));  // httplib's own request, not const
        if (authorized(req)) return httplib::Server::HandlerResponse::Unhandled;
        res.set_header("WWW-Authenticate", "Bearer");
        refuseUnread(req, res, 401, reasonFor(401));
        return httplib::Server::HandlerResponse::Handled;
    });
    // Errors httplib produces itself (no route, 413, unparsable requests) get a JSON body
    // too; responses that already have one are left alone.
    httplib::Server::HandlerWithResponse onError = [](const httplib::Request& req, httplib::Response& res) {
        if (!res.body.empty() || res.content_provider_) return httplib::Server::HandlerResponse::Unhandled;
        // A known route asked with another method: 405 and the methods it takes (RFC 9110 15.5.6).
        if (res.status == 404) {
            if (std::string allowed = allowedMethods(req.path); !allowed.empty()) {
                res.status = 405;
                res.set_header("Allow", allowed);
                sendError(res, 405, req.method + " is not one of this route's methods: " + allowed);
                return httplib::Server::HandlerResponse::Handled;
            }
        }
        sendError(res, res.status, reasonFor(res.status));
        return httplib::Server::HandlerResponse::Handled;
    };
    server_.set_error_handler(onError);
    server_.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr e) {
        sendException(res, e);
    });
    // The access log: one line per answered request (streams when they end).
    server_.set_logger([this](const httplib::Request& req, const httplib::Response& res) {
        context_.service.metrics().countRequest(routeLabel(req.method, req.path), res.status);
        spdlog::info("{} {} {} {} {}", clientAddress(req), req.method, req.path, res.status, res.body.size());
    });
    std::error_code ec;
    if (!config.webRoot.empty() && std::filesystem::is_directory(config.webRoot, ec))
        server_.set_mount_point("/", config.webRoot);
    registerRoutes(server_, context_);
}

int HttpServer::bind(const std::string& host, int port) {
    // httplib reads the host as the socket path for AF_UNIX; the port is not used.
    server_.set_address_family(AF_UNIX);
    if (!server_.bind_to_port(socketFolder_ + "/http.sock", 80)) return -1;
    int bound = guard_.bind(host, port);
    origin_.boundHost = host;
    origin_.port = bound;
    return bound;
}

}  // namespace photon::api
