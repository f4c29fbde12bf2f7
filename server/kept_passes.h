// Which passes of a render are kept as images for comparison: the first pass at or after
// each power of two (1, 2, 4, 8, ...), so a render of N passes keeps about log2 N of them
// whichever passes it reports (a farm's batches end at multiples of their size).
#pragma once
#include <algorithm>
#include <bit>
#include <vector>

namespace photon::server {

// True if no pass in `kept` lies in the same power-of-two range [2^k, 2^(k+1)) as `pass`.
inline bool isKeptPass(int pass, const std::vector<int>& kept) {
    if (pass < 1) return false;
    const auto range = std::bit_width(unsigned(pass));
    return std::none_of(kept.begin(), kept.end(), [&](int k) { return k >= 1 && std::bit_width(unsigned(k)) == range; });
}

}  // namespace photon::server
