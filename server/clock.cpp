#include "clock.h"
#include <chrono>
#include <cstdio>
#include <ctime>
#include <random>

namespace photon::server {

std::string utcNowIso8601() {
    using namespace std::chrono;
    auto now = system_clock::now();
    std::time_t seconds = system_clock::to_time_t(now);
    auto millis = duration_cast<milliseconds>(now.time_since_epoch()).count() % 1000;
    std::tm utc{};
    gmtime_r(&seconds, &utc);
    char buf[96];  // room for any int the compiler cannot rule out
    std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", utc.tm_year + 1900, utc.tm_mon + 1,
                  utc.tm_mday, utc.tm_hour, utc.tm_min, utc.tm_sec, static_cast<int>(millis));
    return buf;
}

std::string randomJobId() {
    // random_device reads the OS entropy source; one per call is cheap next to a render.
    std::random_device device;
    uint64_t bits = (uint64_t(device()) << 32) ^ device();
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(bits));
    return buf;
}

}  // namespace photon::server
