// Who sent a request. The HTTP server's peer is the connection guard; the guard names the
// client's address in a header field of every request it forwards (dropping any the client
// sent), and this reads it.
#pragma once
#include <string>

namespace httplib {
struct Request;
}

namespace photon::api {

inline constexpr const char* kClientAddressField = "X-Photon-Client-Address";

std::string clientAddress(const httplib::Request& req);

}  // namespace photon::api
