#include "api/stream_support.h"
#include <string>
#include "server/errors.h"

namespace photon::api {

std::shared_ptr<StreamSlots::Slot> StreamSlots::acquire() {
    if (++used_ > max_) {
        --used_;
        throw server::ServiceError(server::ErrorKind::Unavailable,
                                   "too many open streams: all " + std::to_string(max_) +
                                       " allowed by the server limit (--max-streams) are in use; retry later");
    }
    return std::make_shared<Slot>(*this);
}

}  // namespace photon::api
