#include "api/client_address.h"
#include <httplib.h>

namespace photon::api {

std::string clientAddress(const httplib::Request& req) {
    std::string address = req.get_header_value(kClientAddressField);
    return address.empty() ? req.remote_addr : address;
}

}  // namespace photon::api
