// Header fields the connection guard sets on every request it forwards (any the client sent
// under these names are dropped), and their readers:
//  - the client's address: the HTTP server's peer is the guard, not the client;
//  - the names of fields the client sent with an empty value, which httplib's parser drops
//    (an empty Idempotency-Key must be refused, not taken for none).
#pragma once
#include <string>
#include <string_view>

namespace httplib {
struct Request;
}

namespace photon::api {

inline constexpr const char* kClientAddressField = "X-Photon-Client-Address";
inline constexpr const char* kEmptyFieldsField = "X-Photon-Empty-Fields";

// Who sent the request.
std::string clientAddress(const httplib::Request& req);
// The client sent the field `name` with an empty value.
bool sentEmpty(const httplib::Request& req, std::string_view name);

}  // namespace photon::api
