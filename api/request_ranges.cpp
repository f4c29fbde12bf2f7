#include "api/request_ranges.h"
#include <limits>

namespace photon::api {

std::vector<std::pair<long, long>> rangesToHonour(const std::string& path,
                                                  const std::vector<std::pair<long, long>>& ranges) {
    const bool readWhole = path.rfind("/api/", 0) == 0 || path == "/metrics";
    if (readWhole || ranges.empty() || ranges.size() > kMaxRanges) return {};
    if (ranges.size() == 1) return ranges;  // one range of any form, a suffix range included
    long end = -1;  // the last byte taken so far
    for (const auto& [first, last] : ranges) {
        if (first < 0 || first <= end || (last >= 0 && last < first)) return {};
        end = last < 0 ? std::numeric_limits<long>::max() : last;  // an open range takes the rest
    }
    return ranges;
}

}  // namespace photon::api
