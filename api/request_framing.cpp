#include "api/request_framing.h"
#include <httplib.h>
#include <algorithm>
#include <cctype>
#include <charconv>

namespace photon::api {

std::variant<BodyFraming, Refusal> bodyFramingOf(const RequestHead& head) {
    std::vector<std::string> lengths = head.values("Content-Length");
    std::vector<std::string> codings = head.values("Transfer-Encoding");
    BodyFraming framing;
    for (const std::string& value : lengths) {
        if (value.empty() || !std::all_of(value.begin(), value.end(), [](unsigned char c) { return std::isdigit(c); }))
            return Refusal{400, "Content-Length: expected a whole number of bytes, got \"" + value + "\""};
        if (value != lengths.front()) return Refusal{400, "two different Content-Length headers"};
        if (std::from_chars(value.data(), value.data() + value.size(), framing.length).ec != std::errc())
            return Refusal{413, "request body too large"};
    }
    if (codings.empty()) return framing;
    if (!lengths.empty()) return Refusal{400, "both Transfer-Encoding and Content-Length"};
    if (codings.size() > 1 || !equalsIgnoringCase(codings.front(), "chunked"))
        return Refusal{400, "Transfer-Encoding: only chunked is accepted"};
    framing.kind = BodyFraming::Kind::Chunked;
    return framing;
}

std::optional<Refusal> checkRequestPath(const httplib::Request& req) {
    if (std::any_of(req.path.begin(), req.path.end(), [](unsigned char c) { return c < 0x20 || c == 0x7f; }))
        return Refusal{404, "no such route or file: the path holds a control character"};
    return std::nullopt;
}

}  // namespace photon::api
