// The time since `start` in milliseconds, for the pass statistics (PassStats) the
// integrators report.
#pragma once
#include <chrono>

namespace photon {

inline double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace photon
