// Wall-clock timestamps and job ids: the two things the service makes up itself.
#pragma once
#include <string>

namespace photon::server {

// Now as ISO 8601 UTC with milliseconds, e.g. "2024-05-01T12:34:56.789Z".
std::string utcNowIso8601();

// 16 lowercase hex digits (64 random bits): unguessable enough that job URLs are not
// enumerable, short enough to read.
std::string randomJobId();

}  // namespace photon::server
