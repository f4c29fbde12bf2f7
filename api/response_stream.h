// The HTTP server's side of a connection, followed as its bytes pass through the connection
// guard (they are forwarded unchanged): where each response ends (RFC 9112 section 6.3), so
// the guard knows when the server has answered everything it was asked. Then the guard hands
// the server the client's next request, or, with none waiting, lets the server's connection
// go: httplib holds a thread for every connection it keeps alive, and a client that keeps its
// connection open between requests must not hold one.
#pragma once
#include <cstddef>
#include <deque>
#include <string>
#include <string_view>
#include "api/chunked_body.h"

namespace photon::api {

class ResponseStream {
public:
    // A request went on; `method` tells whether its response has a body (HEAD's has none),
    // `endsConnection` that the connection ends with its answer.
    void expect(const std::string& method, bool endsConnection = false) {
        pending_.push_back({method == "HEAD", endsConnection});
    }
    // Takes the server's next bytes. False if they are not HTTP/1.1 responses.
    bool consume(std::string_view bytes);
    // The server closed its side: a response without a length ends there.
    void serverClosed();

    // Requests not yet wholly answered.
    size_t outstanding() const { return pending_.size(); }
    // A final response said "Connection: close" or ends only when the connection does.
    bool closesConnection() const { return closes_; }

private:
    enum class State { Head, Length, Chunked, UntilClose };
    bool headEnded();  // parses head_; false if malformed
    void responseEnded();

    struct Pending {
        bool head;
        bool endsConnection;
    };
    std::deque<Pending> pending_;
    State state_ = State::Head;
    std::string head_;
    uint64_t left_ = 0;
    ChunkedBodyScanner chunks_;
    std::string scratch_;
    bool closes_ = false;
};

}  // namespace photon::api
