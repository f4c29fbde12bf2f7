// Where a request comes from, checked before anything else is done with it: a web page the
// user visits must not be able to queue or cancel jobs on a server on their machine
// (cross-site request forgery), nor read it through a name it rebinds to 127.0.0.1 (DNS
// rebinding). Browsers say where a request comes from (Origin, Sec-Fetch-Site) and what
// name it was sent to (Host); non-browser clients send neither Origin nor a foreign Host.
#pragma once
#include <optional>
#include <string>
#include <vector>
#include "api/refusal.h"

namespace httplib {
struct Request;
}

namespace photon::api {

struct OriginPolicy {
    std::string boundHost;  // the address the server listens on, as given (--host)
    int port = 0;           // the port it listens on
    std::vector<std::string> allowedHosts;    // --allow-host: more names it may be reached by
    std::vector<std::string> allowedOrigins;  // --allow-origin: other sites that may send
};

// Nothing when the request may go on; otherwise the status and the reason:
//  - 421 when Host names neither the bound address, a loopback name when it is a loopback
//    address, nor an --allow-host entry (with or without the port). A server bound to every
//    address (0.0.0.0, ::) takes any Host unless --allow-host narrows it.
//  - 403 for a request that changes something (any method but GET, HEAD and OPTIONS) whose
//    Origin is another site than the one it was sent to and not an --allow-origin entry, or
//    that a browser marks Sec-Fetch-Site: cross-site without an allowed Origin.
//  - 415 for a request with a body that is neither application/json nor multipart/form-data.
std::optional<Refusal> checkRequestOrigin(const httplib::Request& req, const OriginPolicy& policy);

}  // namespace photon::api
