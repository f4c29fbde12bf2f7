#include "integrators/common/pass_halves.h"
#include <cmath>
#include "integrators/common/checkpoint.h"

namespace photon {

void PassHalves::save(std::ostream& out) const {
    if (!known_) return;
    writeRaw(out, counts_, 2);
    writeRaw(out, sums_.data(), sums_.size());
}

void PassHalves::restore(std::istream& in, int64_t passes) {
    if (in.peek() == std::char_traits<char>::eof()) {
        in.clear();
        known_ = false;
        return;
    }
    int64_t counts[2];
    readRaw(in, counts, 2);
    // Each count checked against the passes before they are added: a damaged count near
    // 2^63 must not overflow the sum.
    if (counts[0] < 0 || counts[1] < 0 || counts[0] > passes || counts[1] != passes - counts[0])
        throw CheckpointError("checkpoint: invalid pass halves");
    std::vector<float> sums(sums_.size());
    readRaw(in, sums.data(), sums.size());
    for (float s : sums)
        if (!(s >= 0 && std::isfinite(s))) throw CheckpointError("checkpoint: invalid pass halves");
    requireEndOfCheckpoint(in);
    sums_ = std::move(sums);
    counts_[0] = counts[0], counts_[1] = counts[1];
    known_ = true;
}

}  // namespace photon
