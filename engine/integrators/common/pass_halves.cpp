#include "integrators/common/pass_halves.h"
#include <cmath>
#include "integrators/common/checkpoint.h"

namespace photon {

std::optional<PixelErrors> PassHalves::errors(const Image& image, double decay) const {
    if (!known_) return std::nullopt;
    PixelErrors e;
    e.width = image.width, e.height = image.height, e.decay = decay;
    const size_t n = size_t(image.width) * image.height;
    e.luminance.resize(n);
    e.variance.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const float* c = &image.rgb[3 * i];
        e.luminance[i] = luminance(Color(c[0], c[1], c[2]));
        e.variance[i] = halfSplitVariance(sums_[2 * i + 1], sums_[2 * i], counts_[1], counts_[0]);
    }
    return e;
}

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
    if (counts[0] < 0 || counts[1] < 0 || counts[0] + counts[1] != passes) throw CheckpointError("checkpoint: invalid pass halves");
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
