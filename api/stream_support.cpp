#include "api/stream_support.h"
#include <string>
#include "server/errors.h"
#include "server/service_limits.h"

namespace photon::api {

std::shared_ptr<StreamSlots::Slot> StreamSlots::acquire() {
    if (++used_ > max_) {
        --used_;
        throw server::ServiceError(server::ErrorKind::Unavailable,
                                   "too many open streams: all " + std::to_string(max_) + " allowed by the server limit (" +
                                       server::optionOf(&server::Limits::maxStreams) + ") are in use; retry later");
    }
    return std::make_shared<Slot>(*this);
}

httplib::ContentProviderResourceReleaser StreamSlots::countWriting() {
    std::lock_guard lock(writingMutex_);
    ++writing_;
    return [this](bool) {
        std::lock_guard lock(writingMutex_);
        if (--writing_ == 0) written_.notify_all();
    };
}

bool StreamSlots::waitUntilWritten(std::chrono::milliseconds timeout) {
    std::unique_lock lock(writingMutex_);
    return written_.wait_for(lock, timeout, [this] { return writing_ == 0; });
}

}  // namespace photon::api
