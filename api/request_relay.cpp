#include "api/request_relay.h"
#include <algorithm>
#include <variant>
#include "api/guard_fields.h"
#include "api/request_framing.h"

namespace photon::api {

namespace {

// Whether the Connection field's tokens hold `option` (they are comma-separated).
bool connectionHas(const RequestHead& head, std::string_view option) {
    for (const std::string& value : head.values("Connection")) {
        std::string_view rest(value);
        while (!rest.empty()) {
            size_t comma = rest.find(',');
            std::string_view token = rest.substr(0, comma);
            while (!token.empty() && token.front() == ' ') token.remove_prefix(1);
            while (!token.empty() && token.back() == ' ') token.remove_suffix(1);
            if (equalsIgnoringCase(token, option)) return true;
            rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
        }
    }
    return false;
}

bool endsConnection(const RequestHead& head) {
    if (connectionHas(head, "close")) return true;
    return head.version == "HTTP/1.0" && !connectionHas(head, "keep-alive");
}

}  // namespace

size_t RequestRelay::feed(std::string_view bytes, std::string& forward) {
    const size_t offered = bytes.size();
    // Bytes after a head: a suffix of `bytes` (the head ends in them, or it would have ended
    // in an earlier call), so what is left of them counts as not taken.
    std::string leftover;
    bool requestEnded = false;
    while (!bytes.empty() && !refused_ && !requestEnded) {
        if (phase_ == Phase::Head) {
            head_.append(bytes);
            bytes = {};
            HeadScan scan = scanRequestHead(head_, limits_);
            if (scan.state == HeadScan::State::Incomplete) break;
            if (scan.state == HeadScan::State::Refused) {
                refused_ = scan.refusal;
                break;
            }
            auto framing = bodyFramingOf(scan.head);
            if (auto* refusal = std::get_if<Refusal>(&framing)) {
                refused_ = *refusal;
                break;
            }
            forward += forwardedHead(scan.head, clientAddress_);
            ++requests_;
            method_ = scan.head.method;
            endsConnection_ = endsConnection(scan.head);
            leftover = head_.substr(scan.length);
            head_.clear();
            bytes = leftover;
            const BodyFraming& body = std::get<BodyFraming>(framing);
            bodyBytes_ = 0;
            if (body.kind == BodyFraming::Kind::Chunked) {
                phase_ = Phase::Chunked;
                chunks_ = ChunkedBodyScanner(limits_.maxBytes);
            } else if (body.length > 0) {
                phase_ = Phase::Body;
                bodyLeft_ = body.length;
            } else {
                requestEnded = true;
            }
        } else if (phase_ == Phase::Body) {
            size_t take = size_t(std::min<uint64_t>(bodyLeft_, bytes.size()));
            forward.append(bytes.substr(0, take));
            bytes.remove_prefix(take);
            bodyLeft_ -= take;
            bodyBytes_ += take;
            if (bodyLeft_ == 0) phase_ = Phase::Head, requestEnded = true;
        } else {
            size_t take = chunks_.consume(bytes, forward);
            bytes.remove_prefix(take);
            bodyBytes_ += take;
            if (chunks_.error()) refused_ = chunks_.error();
            else if (chunks_.done()) phase_ = Phase::Head, requestEnded = true;
        }
    }
    return refused_ ? offered : offered - bytes.size();
}

}  // namespace photon::api
