// A request's target and framing, checked before anything is read past its head.
//
// Where a request's body ends must be beyond doubt (RFC 9112 section 6.3): a server and a
// proxy in front of it that read it differently let one request smuggle another. So a
// request with two different Content-Length values, a Content-Length that is not a whole
// non-negative number, or both Transfer-Encoding and Content-Length, is refused (400), as is
// a transfer coding other than chunked. The connection guard applies this to every head it
// reads; the body it then forwards is exactly what this framing says.
//
// The target's path, once %-decoded, must not hold a NUL or another control character: no
// route or file has one, and a NUL cuts the name a file is opened by short (the page's
// "index.html%00.js" was served as JavaScript): 404.
#pragma once
#include <cstdint>
#include <optional>
#include <variant>
#include "api/refusal.h"
#include "api/request_head.h"

namespace httplib {
struct Request;
}

namespace photon::api {

struct BodyFraming {
    enum class Kind { Length, Chunked } kind = Kind::Length;
    uint64_t length = 0;  // for Length; a request with neither field has length 0
};

std::variant<BodyFraming, Refusal> bodyFramingOf(const RequestHead& head);

std::optional<Refusal> checkRequestPath(const httplib::Request& req);

}  // namespace photon::api
