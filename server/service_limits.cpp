#include "service_limits.h"

namespace photon::server {

void checkLimit(ErrorKind kind, const std::string& what, int64_t value, int64_t limit, const char* option) {
    if (value <= limit) return;
    throw ServiceError(kind, what + " " + std::to_string(value) + " exceeds the server limit of " +
                                 std::to_string(limit) + " (" + option + ")");
}

}  // namespace photon::server
