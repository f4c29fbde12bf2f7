// A request's head (request line and header fields), read by the connection guard before
// any of it reaches the HTTP server, under fixed bounds: a client cannot make the server
// buffer an unbounded line or an unbounded number of header fields before it is known who
// the client is.
//
// The head is parsed strictly (RFC 9112 sections 2.2, 3 and 5): every line ends in CRLF, a
// bare CR or LF, a field without a colon, whitespace before the colon and obsolete line
// folding are refused (400). Whatever passes is forwarded re-serialised from what was parsed,
// so the HTTP server behind cannot read a different request from the same bytes.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>
#include "api/refusal.h"

namespace photon::api {

struct HeadLimits {
    size_t maxBytes = 64 << 10;  // request line and fields with their CRLFs
    size_t maxFields = 100;
};

using HeaderFields = std::vector<std::pair<std::string, std::string>>;

struct RequestHead {
    std::string method, target, version;
    HeaderFields fields;  // in the order sent; names as sent, values without surrounding whitespace

    // Values of the field `name` (case-insensitive), in order.
    std::vector<std::string> values(std::string_view name) const;
};

struct HeadScan {
    enum class State { Incomplete, Complete, Refused } state = State::Incomplete;
    size_t length = 0;  // bytes of the buffer the head took, its final CRLFCRLF included
    RequestHead head;   // when Complete
    Refusal refusal;    // when Refused: 400, 414 (request line) or 431 (fields)
};

// Looks for a whole head at the start of `buffered`. Empty lines before the request line are
// skipped (RFC 9112 section 2.2) and counted in `length`.
HeadScan scanRequestHead(std::string_view buffered, const HeadLimits& limits);

// The head as sent to the HTTP server: the same request line and fields, with the guard's
// own fields (guard_fields.h) in place of any the client sent under their names.
std::string forwardedHead(const RequestHead& head, const std::string& clientAddress);

bool equalsIgnoringCase(std::string_view a, std::string_view b);
// A field value without the spaces and tabs around it (RFC 9110 section 5.5).
std::string_view trimmed(std::string_view s);

}  // namespace photon::api
