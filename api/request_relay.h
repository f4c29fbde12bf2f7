// One client connection's requests as a byte stream, without sockets: heads are read under
// their bounds (request_head.h) and framed (request_framing.h), and what goes on to the HTTP
// server is produced: each head re-serialised with the client's address, each body exactly as
// long as its framing says (a chunked one re-framed, chunked_body.h). The connection guard
// runs one per connection; the HTTP fuzzer runs its inputs through one, as the server sees them.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include "api/chunked_body.h"
#include "api/refusal.h"
#include "api/request_head.h"

namespace photon::api {

class RequestRelay {
public:
    RequestRelay(const HeadLimits& limits, std::string clientAddress)
        : limits_(limits), clientAddress_(std::move(clientAddress)), chunks_(limits.maxBytes) {}

    // Takes the client's next bytes, up to the end of the request they are in, and appends
    // what the server is to get to `forward`; returns how many it took (the rest belong to
    // the next request: feed them again when it may go on). A refusal ends the stream:
    // nothing more is taken.
    size_t feed(std::string_view bytes, std::string& forward);
    const std::optional<Refusal>& refusal() const { return refused_; }

    // Requests whose heads have gone on, so far, and the method of the last one.
    int64_t requestsForwarded() const { return requests_; }
    const std::string& lastMethod() const { return method_; }
    // The last request asked for its connection to end with its answer: "Connection: close",
    // or HTTP/1.0 without "Connection: keep-alive" (RFC 9112 section 9.3).
    bool lastEndsConnection() const { return endsConnection_; }
    // Bytes of a head are waiting for the rest of it.
    bool midHead() const { return phase_ == Phase::Head && !head_.empty(); }
    // A body is being relayed; its bytes so far.
    bool inBody() const { return phase_ != Phase::Head; }
    uint64_t bodyBytes() const { return bodyBytes_; }

private:
    enum class Phase { Head, Body, Chunked };

    HeadLimits limits_;
    std::string clientAddress_;
    Phase phase_ = Phase::Head;
    std::string head_;
    uint64_t bodyLeft_ = 0;
    uint64_t bodyBytes_ = 0;
    ChunkedBodyScanner chunks_;
    int64_t requests_ = 0;
    std::string method_;
    bool endsConnection_ = false;
    std::optional<Refusal> refused_;
};

}  // namespace photon::api
