#include "api/request_framing.h"
#include <httplib.h>
#include <algorithm>
#include <cctype>

namespace photon::api {

std::optional<Refusal> checkRequestFraming(const httplib::Request& req) {
    if (std::any_of(req.path.begin(), req.path.end(), [](unsigned char c) { return c < 0x20 || c == 0x7f; }))
        return Refusal{404, "no such route or file: the path holds a control character"};
    auto [first, end] = req.headers.equal_range("Content-Length");
    for (auto it = first; it != end; ++it) {
        const std::string& value = it->second;
        if (value.empty() || !std::all_of(value.begin(), value.end(), [](unsigned char c) { return std::isdigit(c); }))
            return Refusal{400, "Content-Length: expected a whole number of bytes, got \"" + value + "\""};
        if (value != first->second) return Refusal{400, "two different Content-Length headers"};
    }
    if (req.has_header("Transfer-Encoding")) {
        if (first != end) return Refusal{400, "both Transfer-Encoding and Content-Length"};
        std::string coding = req.get_header_value("Transfer-Encoding");
        std::transform(coding.begin(), coding.end(), coding.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if (coding != "chunked" || req.get_header_value_count("Transfer-Encoding") > 1)
            return Refusal{400, "Transfer-Encoding: only chunked is accepted"};
    }
    return std::nullopt;
}

}  // namespace photon::api
