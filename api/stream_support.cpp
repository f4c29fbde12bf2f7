#include "api/stream_support.h"
#include "server/errors.h"

namespace photon::api {

std::shared_ptr<StreamSlots::Slot> StreamSlots::acquire() {
    if (++used_ > max_) {
        --used_;
        throw server::ServiceError(server::ErrorKind::Unavailable, "too many open streams; retry later");
    }
    return std::make_shared<Slot>(*this);
}

}  // namespace photon::api
