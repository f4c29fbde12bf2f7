// A request's target and framing, checked before anything is read past its head.
//
// The target's path, once %-decoded, must not hold a NUL or another control character: no
// route or file has one, and a NUL cuts the name a file is opened by short (the page's
// "index.html%00.js" was served as JavaScript): 404.
//
// Where a request's body ends must be beyond doubt (RFC 9112 section 6.3): a server and a
// proxy in front of it that read it differently let one request smuggle another. So a
// request with two different Content-Length values, a Content-Length that is not a whole
// non-negative number, or both Transfer-Encoding and Content-Length, is refused (400), as is
// a transfer coding other than chunked.
#pragma once
#include <optional>
#include "api/refusal.h"

namespace httplib {
struct Request;
}

namespace photon::api {

std::optional<Refusal> checkRequestFraming(const httplib::Request& req);

}  // namespace photon::api
