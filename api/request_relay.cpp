#include "api/request_relay.h"
#include <algorithm>
#include <variant>
#include "api/client_address.h"
#include "api/request_framing.h"

namespace photon::api {

std::optional<Refusal> RequestRelay::feed(std::string_view bytes, std::string& forward) {
    std::string leftover;  // bytes after a head, for what follows it
    while (!bytes.empty() && !refused_) {
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
            forward += forwardedHead(scan.head, kClientAddressField, clientAddress_);
            ++requests_;
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
            }
        } else if (phase_ == Phase::Body) {
            size_t take = size_t(std::min<uint64_t>(bodyLeft_, bytes.size()));
            forward.append(bytes.substr(0, take));
            bytes.remove_prefix(take);
            bodyLeft_ -= take;
            bodyBytes_ += take;
            if (bodyLeft_ == 0) phase_ = Phase::Head;
        } else {
            size_t take = chunks_.consume(bytes, forward);
            bytes.remove_prefix(take);
            bodyBytes_ += take;
            if (chunks_.error()) refused_ = chunks_.error();
            else if (chunks_.done()) phase_ = Phase::Head;
        }
    }
    return refused_;
}

}  // namespace photon::api
