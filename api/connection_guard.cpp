#include "api/connection_guard.h"
#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <spdlog/spdlog.h>
#include <sys/epoll.h>
#include <sys/eventfd.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <unordered_map>
#include "api/errors.h"
#include "api/request_relay.h"
#include "api/response_stream.h"

namespace photon::api {

namespace {

using Clock = std::chrono::steady_clock;

constexpr size_t kReadChunk = 16 << 10;
// Bytes held for either direction of a connection before reading from the other side pauses.
constexpr size_t kMaxBuffered = 256 << 10;
// A client that takes none of a response for this long is gone (httplib's own write timeout
// is 5 s; a client on a slow link still takes something every few seconds).
constexpr double kStalledWriteSeconds = 30;
// After a last response, unread client bytes are read and dropped for this long before the
// socket closes: closing with unread bytes sends a reset that can destroy the response.
constexpr double kLingerSeconds = 2;
// Retry of a connection to the HTTP server whose accept backlog is full.
constexpr int kRetryMilliseconds = 10;
constexpr int kTimerMilliseconds = 250;
constexpr uint64_t kListenTag = 0;
constexpr uint64_t kWakeTag = 1;

double secondsBetween(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

std::string refusalResponse(const Refusal& refusal) {
    std::string body = problemBody({refusal.status, refusal.message});
    std::string head = "HTTP/1.1 " + std::to_string(refusal.status) + " " + reasonPhrase(refusal.status) +
                       "\r\nContent-Type: " + kProblemJson + "\r\nContent-Length: " + std::to_string(body.size()) +
                       "\r\nConnection: close\r\n";
    if (refusal.status == 503) head += "Retry-After: " + std::to_string(kRetryAfterSeconds) + "\r\n";
    return head + "\r\n" + body;
}

std::string peerAddress(const sockaddr_storage& peer) {
    char text[INET6_ADDRSTRLEN] = "";
    if (peer.ss_family == AF_INET)
        inet_ntop(AF_INET, &reinterpret_cast<const sockaddr_in&>(peer).sin_addr, text, sizeof text);
    else if (peer.ss_family == AF_INET6)
        inet_ntop(AF_INET6, &reinterpret_cast<const sockaddr_in6&>(peer).sin6_addr, text, sizeof text);
    return text;
}

// Two descriptors a connection: enough of them for maxConnections.
void raiseDescriptorLimit(int64_t connections) {
    rlimit limit{};
    if (getrlimit(RLIMIT_NOFILE, &limit) != 0) return;
    rlim_t wanted = rlim_t(2 * connections + 1024);
    if (limit.rlim_cur >= wanted) return;
    limit.rlim_cur = limit.rlim_max == RLIM_INFINITY ? wanted : std::min(wanted, limit.rlim_max);
    setrlimit(RLIMIT_NOFILE, &limit);
}

struct Connection {
    Connection(uint64_t id, int client, const std::string& address, const HeadLimits& limits)
        : id(id), client(client), address(address), requests(limits, address) {}

    uint64_t id;
    int client;
    int upstream = -1;  // open while the server is answering a request of this connection
    std::string address;
    RequestRelay requests;
    ResponseStream responses;
    bool closing = false;  // no more requests: what is on its way is delivered, then it closes
    Clock::time_point accepted;
    Clock::time_point idleSince;  // since when a next request is due (see headDue)
    Clock::time_point bodyStart;

    std::string fromClient;  // client bytes the relay has not taken yet (a next request)
    std::string toUpstream, toClient;
    Clock::time_point clientWriteProgress;  // last time toClient shrank or began to fill
    bool connectPending = false;
    Clock::time_point connectSince;
    bool clientEof = false;
    bool lingering = false;
    Clock::time_point lingerSince;
    uint32_t clientEvents = 0, upstreamEvents = 0;
    bool closed = false;

    // Everything asked is answered and no body is on its way: the next request's head is due
    // within headSeconds (the first from connecting, a next one from the last answer).
    bool headDue() const { return !closing && responses.outstanding() == 0 && !requests.inBody(); }
    // Holds no server connection: may be closed to make room for another client.
    bool idle() const { return headDue() && upstream < 0 && !connectPending && toClient.empty(); }
};

}  // namespace

class ConnectionGuard::Loop {
public:
    Loop(const GuardLimits& limits, std::string upstreamSocket)
        : limits_(limits), upstreamSocket_(std::move(upstreamSocket)) {
        epoll_ = epoll_create1(EPOLL_CLOEXEC);
        wake_ = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
        add(wake_, EPOLLIN, kWakeTag);
        raiseDescriptorLimit(limits.maxConnections);
    }
    ~Loop() {
        for (auto& [id, c] : connections_) closeDescriptors(*c);
        if (listen_ >= 0) close(listen_);
        close(wake_);
        close(epoll_);
    }

    int bind(const std::string& host, int port) {
        addrinfo hints{};
        hints.ai_family = AF_UNSPEC;
        hints.ai_socktype = SOCK_STREAM;
        hints.ai_flags = AI_PASSIVE | AI_NUMERICSERV;
        addrinfo* found = nullptr;
        if (getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &found) != 0) return -1;
        int bound = -1;
        for (addrinfo* a = found; a && bound < 0; a = a->ai_next) {
            int fd = socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol);
            if (fd < 0) continue;
            int one = 1;
            setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
            if (::bind(fd, a->ai_addr, a->ai_addrlen) == 0 && listen(fd, SOMAXCONN) == 0) {
                sockaddr_storage local{};
                socklen_t length = sizeof local;
                getsockname(fd, reinterpret_cast<sockaddr*>(&local), &length);
                bound = ntohs(local.ss_family == AF_INET6 ? reinterpret_cast<sockaddr_in6&>(local).sin6_port
                                                          : reinterpret_cast<sockaddr_in&>(local).sin_port);
                listen_ = fd;
            } else {
                close(fd);
            }
        }
        freeaddrinfo(found);
        if (listen_ >= 0) add(listen_, EPOLLIN, kListenTag);
        return bound;
    }

    void run() {
        epoll_event events[256];
        Clock::time_point nextTimers = Clock::now();
        Clock::time_point drainUntil{};
        while (true) {
            if (stopping_ && drainUntil == Clock::time_point{}) beginDrain(drainUntil);
            if (stopping_ && (connections_.empty() || Clock::now() > drainUntil)) break;
            int timeout = anyConnectPending() ? kRetryMilliseconds : kTimerMilliseconds;
            int n = epoll_wait(epoll_, events, 256, timeout);
            for (int i = 0; i < n; ++i) dispatch(events[i]);
            if (Clock::now() >= nextTimers || anyConnectPending()) {
                checkTimers();
                nextTimers = Clock::now() + std::chrono::milliseconds(kTimerMilliseconds);
            }
        }
    }

    void stop() {
        stopping_ = true;
        uint64_t one = 1;
        [[maybe_unused]] ssize_t w = write(wake_, &one, sizeof one);
    }

private:
    void add(int fd, uint32_t events, uint64_t tag) {
        epoll_event e{};
        e.events = events;
        e.data.u64 = tag;
        epoll_ctl(epoll_, EPOLL_CTL_ADD, fd, &e);
    }
    void modify(int fd, uint32_t events, uint64_t tag) {
        epoll_event e{};
        e.events = events;
        e.data.u64 = tag;
        epoll_ctl(epoll_, EPOLL_CTL_MOD, fd, &e);
    }
    static uint64_t tagOf(const Connection& c, bool upstream) { return (c.id << 1) | (upstream ? 1 : 0); }

    // Stop taking connections and requests; answers in flight are relayed for a while.
    void beginDrain(Clock::time_point& until) {
        until = Clock::now() + std::chrono::seconds(2);
        if (listen_ >= 0) {
            close(listen_);
            listen_ = -1;
        }
        // Connections with nothing in the server's hands close once what is on its way to
        // them is sent (a stream's last chunk, say); the others when the server ends theirs.
        for (auto& [id, c] : connections_) {
            if (c->upstream >= 0 || c->connectPending) continue;
            c->closing = true;
            settle(*c);
        }
        sweep();
    }

    bool anyConnectPending() const { return pendingConnects_ > 0; }

    void dispatch(const epoll_event& e) {
        if (e.data.u64 == kListenTag) return acceptAll();
        if (e.data.u64 == kWakeTag) {
            uint64_t value;
            [[maybe_unused]] ssize_t r = read(wake_, &value, sizeof value);
            return;
        }
        auto it = connections_.find(e.data.u64 >> 1);
        if (it == connections_.end()) return;
        Connection& c = *it->second;
        if (e.data.u64 & 1) {
            if (e.events & (EPOLLHUP | EPOLLERR)) {
                // The server closed: what it wrote is bounded by its socket buffer; take it all.
                while (c.upstream >= 0 && readUpstream(c)) {
                }
            } else if (e.events & EPOLLIN) {
                readUpstream(c);
            }
            if (!c.closed && c.upstream >= 0 && (e.events & EPOLLOUT)) writeUpstream(c);
        } else {
            // Hang-up: both directions are shut (or reset); nothing can reach the client.
            if (e.events & (EPOLLERR | EPOLLHUP)) c.closed = true;
            if (!c.closed && (e.events & EPOLLIN)) readClient(c);
            if (!c.closed && (e.events & EPOLLOUT)) writeClient(c);
        }
        settle(c);
        sweep();
    }

    void acceptAll() {
        while (true) {
            sockaddr_storage peer{};
            socklen_t length = sizeof peer;
            int fd = accept4(listen_, reinterpret_cast<sockaddr*>(&peer), &length, SOCK_NONBLOCK | SOCK_CLOEXEC);
            if (fd < 0) {
                if (errno == EMFILE || errno == ENFILE) {
                    // Out of descriptors: make room from the oldest idle connection, or wait
                    // for one to end.
                    bool evicted = evictOldestIdle("");
                    sweep();
                    if (evicted) continue;
                    modify(listen_, 0, kListenTag);
                    listenPaused_ = true;
                    return;
                }
                return;
            }
            admit(fd, peerAddress(peer));
        }
    }

    void admit(int fd, const std::string& address) {
        auto known = perClient_.find(address);
        bool room = true;
        if (known != perClient_.end() && known->second >= limits_.maxConnectionsPerClient)
            room = evictOldestIdle(address);
        if (room && int64_t(connections_.size()) >= limits_.maxConnections) room = evictOldestIdle("");
        sweep();
        if (!room) {
            std::string answer = refusalResponse({503, "too many connections; try again later"});
            [[maybe_unused]] ssize_t w = send(fd, answer.data(), answer.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
            close(fd);
            return;
        }
        int one = 1;
        setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
        auto c = std::make_unique<Connection>(nextId_++, fd, address, limits_.head);
        c->accepted = c->idleSince = Clock::now();
        ++perClient_[address];
        c->clientEvents = EPOLLIN;
        add(fd, EPOLLIN, tagOf(*c, false));
        connections_.emplace(c->id, std::move(c));
    }

    // Closes the idle connection (no request in the server's hands) of `address` (any, if
    // empty) that connected first. False if there is none.
    bool evictOldestIdle(const std::string& address) {
        Connection* oldest = nullptr;
        for (auto& [id, c] : connections_)
            if (!c->closed && c->idle() && (address.empty() || c->address == address) &&
                (!oldest || c->accepted < oldest->accepted))
                oldest = c.get();
        if (!oldest) return false;
        spdlog::debug("idle connection from {} closed to make room", oldest->address);
        oldest->closed = true;
        return true;
    }

    void readClient(Connection& c) {
        char buffer[kReadChunk];
        ssize_t n = recv(c.client, buffer, sizeof buffer, 0);
        if (n < 0) {
            if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) c.closed = true;
            return;
        }
        if (n == 0) {
            c.clientEof = true;
            return;
        }
        if (c.closing) return;  // read and dropped (see kLingerSeconds)
        c.fromClient.append(buffer, size_t(n));
        pump(c);
    }

    // Hands the server the client's bytes as the relay frames them: the body of the request in
    // flight, or the next request once the last is answered (httplib answers one request at a
    // time and drops bytes that come early).
    void pump(Connection& c) {
        while (!c.closing && !c.fromClient.empty() && c.toUpstream.size() < kMaxBuffered) {
            bool betweenRequests = !c.requests.midHead() && !c.requests.inBody();
            if (betweenRequests && c.responses.outstanding() > 0) return;
            int64_t before = c.requests.requestsForwarded();
            size_t taken = c.requests.feed(c.fromClient, c.toUpstream);
            c.fromClient.erase(0, taken);
            if (c.requests.refusal()) return refuse(c, *c.requests.refusal());
            if (c.requests.requestsForwarded() > before) {
                c.responses.expect(c.requests.lastMethod(), c.requests.lastEndsConnection());
                c.bodyStart = Clock::now();
                if (c.upstream < 0 && !c.connectPending && !connectUpstream(c)) return;
            }
            if (taken == 0) return;
        }
    }

    bool connectUpstream(Connection& c) {
        int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
        sockaddr_un address{};
        address.sun_family = AF_UNIX;
        std::strncpy(address.sun_path, upstreamSocket_.c_str(), sizeof address.sun_path - 1);
        if (fd >= 0 && connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) {
            if (c.connectPending) --pendingConnects_;
            c.connectPending = false;
            c.upstream = fd;
            c.upstreamEvents = 0;
            add(fd, 0, tagOf(c, true));
            return true;
        }
        int error = errno;
        if (fd >= 0) close(fd);
        if (error == EAGAIN) {  // the server's accept backlog is full: retried shortly
            if (!c.connectPending) {
                c.connectPending = true;
                c.connectSince = Clock::now();
                ++pendingConnects_;
            }
            return true;
        }
        spdlog::error("cannot reach the HTTP server at {}: {}", upstreamSocket_, std::strerror(error));
        refuse(c, {503, "server busy"});
        return false;
    }

    // Answers `refusal` and closes. Requests go on one at a time, so a refusal is for the
    // request in flight, if any: the server's connection is dropped with it.
    void refuse(Connection& c, const Refusal& refusal) {
        if (c.connectPending) --pendingConnects_;
        c.connectPending = false;
        releaseUpstream(c);
        c.closing = true;
        c.toUpstream.clear();
        c.fromClient.clear();
        queueToClient(c, refusalResponse(refusal));
    }

    void releaseUpstream(Connection& c) {
        if (c.upstream < 0) return;
        epoll_ctl(epoll_, EPOLL_CTL_DEL, c.upstream, nullptr);
        close(c.upstream);
        c.upstream = -1;
    }

    void queueToClient(Connection& c, std::string_view bytes) {
        if (c.toClient.empty()) c.clientWriteProgress = Clock::now();
        c.toClient.append(bytes);
    }

    // True if it read something.
    bool readUpstream(Connection& c) {
        char buffer[kReadChunk];
        ssize_t n = recv(c.upstream, buffer, sizeof buffer, 0);
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) return false;
        if (n <= 0) {
            upstreamEnded(c);
            return false;
        }
        std::string_view bytes(buffer, size_t(n));
        queueToClient(c, bytes);
        if (!c.responses.consume(bytes)) {
            spdlog::error("the HTTP server's answer to {} is not HTTP/1.1; connection closed", c.address);
            c.closing = true;
            releaseUpstream(c);
            return false;
        }
        if (c.responses.outstanding() == 0 && !c.requests.inBody()) answered(c);
        return true;
    }

    // Everything asked is answered: the server's connection (and its thread) goes, and the
    // client's next request, if it sent one already, goes on.
    void answered(Connection& c) {
        releaseUpstream(c);
        if (c.responses.closesConnection()) {
            c.closing = true;
            return;
        }
        c.idleSince = Clock::now();
        pump(c);
    }

    // The server closed its side: the end of a response without a length, a response it
    // ended early, or its stopping.
    void upstreamEnded(Connection& c) {
        releaseUpstream(c);
        c.responses.serverClosed();
        c.toUpstream.clear();
        if (c.responses.outstanding() > 0 || c.requests.inBody() || c.responses.closesConnection()) c.closing = true;
        else answered(c);
    }

    void writeClient(Connection& c) {
        if (c.toClient.empty()) return;
        ssize_t n = send(c.client, c.toClient.data(), c.toClient.size(), MSG_NOSIGNAL);
        if (n > 0) {
            c.toClient.erase(0, size_t(n));
            c.clientWriteProgress = Clock::now();
        } else if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) {
            c.closed = true;
        }
    }

    void writeUpstream(Connection& c) {
        if (c.connectPending || c.toUpstream.empty()) return;
        ssize_t n = send(c.upstream, c.toUpstream.data(), c.toUpstream.size(), MSG_NOSIGNAL);
        if (n > 0) {
            c.toUpstream.erase(0, size_t(n));
            pump(c);  // room for more of a body
        } else if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) {
            upstreamEnded(c);
        }
    }

    // What a connection does next, after any event: finish, linger, and which events to wait
    // for.
    void settle(Connection& c) {
        if (c.closed) return;
        if (c.clientEof && !c.closing) {
            // A client that sent its last request and half-closed is answered, then closed; one
            // gone mid-request cannot be.
            bool incomplete = c.requests.midHead() || c.requests.inBody();
            if (c.fromClient.empty() && (incomplete || c.responses.outstanding() == 0)) {
                if (incomplete) c.closed = true;
                else c.closing = true;
                if (c.closed) return;
            }
        }
        if (c.closing && c.upstream < 0 && c.toClient.empty()) {
            if (c.clientEof || stopping_) {
                c.closed = true;
                return;
            }
            if (!c.lingering) {
                shutdown(c.client, SHUT_WR);
                c.lingering = true;
                c.lingerSince = Clock::now();
            }
        }
        uint32_t clientEvents = 0;
        if (!c.clientEof && !stopping_ && (c.closing || c.fromClient.size() < kMaxBuffered)) clientEvents |= EPOLLIN;
        if (!c.toClient.empty()) clientEvents |= EPOLLOUT;
        if (clientEvents != c.clientEvents) {
            modify(c.client, clientEvents, tagOf(c, false));
            c.clientEvents = clientEvents;
        }
        if (c.upstream >= 0) {
            uint32_t upstreamEvents = c.toClient.size() < kMaxBuffered ? uint32_t(EPOLLIN) : 0u;
            if (!c.toUpstream.empty()) upstreamEvents |= EPOLLOUT;
            if (upstreamEvents != c.upstreamEvents) {
                modify(c.upstream, upstreamEvents, tagOf(c, true));
                c.upstreamEvents = upstreamEvents;
            }
        }
    }

    void checkTimers() {
        Clock::time_point now = Clock::now();
        for (auto& [id, cp] : connections_) {
            Connection& c = *cp;
            if (c.closed) continue;
            if (c.connectPending) {
                if (secondsBetween(c.connectSince, now) > limits_.headSeconds) refuse(c, {503, "server busy"});
                else connectUpstream(c);
                if (c.upstream >= 0) writeUpstream(c);
            }
            if (c.headDue() && !c.toClient.empty()) c.idleSince = now;  // an answer is still on its way
            if (c.headDue() && secondsBetween(c.idleSince, now) > limits_.headSeconds) {
                // Part of a head came: say why it ends. An idle kept-alive connection just closes
                // (an answer now could be taken for that of a request crossing it).
                if (c.requests.midHead() || !c.fromClient.empty()) {
                    spdlog::info("{}: no whole request head within {} s", c.address, limits_.headSeconds);
                    refuse(c, {408, "the request's head did not arrive within " +
                                        std::to_string(int(limits_.headSeconds)) + " s"});
                } else {
                    c.closed = true;
                }
            } else if (c.requests.inBody()) {
                double late = secondsBetween(c.bodyStart, now) - limits_.headSeconds;
                if (late > 0 && c.toUpstream.size() < kMaxBuffered &&
                    double(c.requests.bodyBytes()) < double(limits_.minBodyBytesPerSecond) * late) {
                    spdlog::info("{}: request body slower than {} bytes/s", c.address, limits_.minBodyBytesPerSecond);
                    c.closed = true;
                }
            }
            if (!c.toClient.empty() && secondsBetween(c.clientWriteProgress, now) > kStalledWriteSeconds)
                c.closed = true;
            if (c.lingering && secondsBetween(c.lingerSince, now) > kLingerSeconds) c.closed = true;
            settle(c);
        }
        if (listenPaused_ && listen_ >= 0) {
            modify(listen_, EPOLLIN, kListenTag);
            listenPaused_ = false;
        }
        sweep();
    }

    void closeDescriptors(Connection& c) {
        if (c.upstream >= 0) close(c.upstream);
        if (c.client >= 0) close(c.client);
        c.upstream = c.client = -1;
    }

    // Removes the connections marked closed.
    void sweep() {
        for (auto it = connections_.begin(); it != connections_.end();) {
            Connection& c = *it->second;
            if (!c.closed) {
                ++it;
                continue;
            }
            if (c.connectPending) --pendingConnects_;
            closeDescriptors(c);  // closing a descriptor also removes it from the epoll set
            if (--perClient_[c.address] <= 0) perClient_.erase(c.address);
            it = connections_.erase(it);
        }
    }

    GuardLimits limits_;
    std::string upstreamSocket_;
    int epoll_ = -1, wake_ = -1, listen_ = -1;
    bool listenPaused_ = false;
    std::atomic<bool> stopping_{false};
    std::unordered_map<uint64_t, std::unique_ptr<Connection>> connections_;
    std::unordered_map<std::string, int> perClient_;
    uint64_t nextId_ = 2;
    int pendingConnects_ = 0;
};

ConnectionGuard::ConnectionGuard(const GuardLimits& limits, std::string upstreamSocket)
    : loop_(std::make_unique<Loop>(limits, std::move(upstreamSocket))) {}

ConnectionGuard::~ConnectionGuard() = default;

int ConnectionGuard::bind(const std::string& host, int port) { return loop_->bind(host, port); }

void ConnectionGuard::run() {
    running_ = true;
    loop_->run();
    running_ = false;
}

void ConnectionGuard::stop() { loop_->stop(); }

}  // namespace photon::api
