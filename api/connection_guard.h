// The connection guard: what listens on the service's TCP port. One thread with epoll holds
// every client connection, reads each request's head under fixed bounds (request_head.h) and
// in bounded time, and only then hands the request to the HTTP server behind it (httplib on a
// private Unix socket), relaying the body as its framing says and the response as it comes.
//
// Why: httplib serves a connection on one of a fixed number of threads from its first byte,
// restarts its read timeout on every byte and buffers a header line of any length. A client
// sending a byte every few seconds on a few hundred connections held every thread, and one
// sending endless header lines grew the server's memory by gigabytes, before any token was
// checked. Here a slow or idle connection costs a socket and a few kilobytes, not a thread:
//  - a head must be whole within `headSeconds` of connecting or of the last answer (an idle
//    connection is closed then), and hold at most `head.maxBytes` bytes and `head.maxFields` fields (408, 431);
//  - a body must arrive at `minBodyBytesPerSecond` on average once `headSeconds` have passed;
//  - a client address may hold `maxConnectionsPerClient` connections and all clients
//    `maxConnections`: beyond either, the oldest idle connection (none of its requests with
//    the server, nothing on its way to the client) is closed to make room, so a flood of slow connections never locks out a prompt client;
//    when no such connection exists the new one is answered 503.
// Requests go to the server one at a time, each once the last is answered (httplib drops
// pipelined bytes), on a connection closed as soon as everything asked is answered: httplib
// keeps a thread on every connection it keeps alive, so a client between requests must not
// hold one. Buffers are bounded both ways; a reader slower than the server holds it back.
#pragma once
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include "api/guard_fields.h"
#include "api/request_head.h"

namespace photon::api {

struct GuardLimits {
    HeadLimits head;
    double headSeconds = 10;
    int64_t minBodyBytesPerSecond = 1024;
    int64_t maxConnectionsPerClient = 256;
    int64_t maxConnections = 4096;
};

class ConnectionGuard {
public:
    // `upstreamSocket`: the Unix socket path the HTTP server listens on.
    ConnectionGuard(const GuardLimits& limits, std::string upstreamSocket);
    ~ConnectionGuard();
    ConnectionGuard(const ConnectionGuard&) = delete;
    ConnectionGuard& operator=(const ConnectionGuard&) = delete;

    // Binds the TCP port; 0 picks a free one. Returns the port, or -1.
    int bind(const std::string& host, int port);
    // Serves until stop(); blocks. Connections open then are closed.
    void run();
    // From any thread.
    void stop();
    bool running() const { return running_; }

private:
    class Loop;
    std::unique_ptr<Loop> loop_;
    std::atomic<bool> running_{false};
};

}  // namespace photon::api
