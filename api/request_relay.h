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

    // Takes the client's next bytes and appends what the server is to get to `forward`. A
    // refusal ends the stream: nothing more is taken.
    std::optional<Refusal> feed(std::string_view bytes, std::string& forward);

    // Requests whose heads have gone on, so far.
    int64_t requestsForwarded() const { return requests_; }
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
    std::optional<Refusal> refused_;
};

}  // namespace photon::api
