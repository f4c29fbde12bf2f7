#include "api/guard_fields.h"
#include <httplib.h>
#include "api/request_head.h"

namespace photon::api {

std::string clientAddress(const httplib::Request& req) {
    std::string address = req.get_header_value(kClientAddressField);
    return address.empty() ? req.remote_addr : address;
}

bool sentEmpty(const httplib::Request& req, std::string_view name) {
    const std::string field = req.get_header_value(kEmptyFieldsField);  // a copy: the view below reads it
    std::string_view names = field;
    while (!names.empty()) {
        size_t comma = names.find(", ");
        if (equalsIgnoringCase(names.substr(0, comma), name)) return true;
        names = comma == std::string_view::npos ? std::string_view() : names.substr(comma + 2);
    }
    return false;
}

}  // namespace photon::api
