#include "integrators/sppm/adaptive_radius.h"
#include <algorithm>
#include <cmath>
#include <limits>
#include "integrators/common/checkpoint.h"
#include "integrators/sppm/pixel_neighbourhood.h"

namespace photon {

namespace {
// Marks the block in a checkpoint: no pass count of the halves that may follow instead
// (PassHalves, an int64 below 2^31) can equal it.
constexpr uint64_t kRadiusTag = 0x5355494441524441ull;  // "ADRADIUS"
constexpr uint32_t kMostSpreadPhotons = 1u << 21;            // PhotonSpread: 2^21 photons of 2^11 units fill 32 bits
}  // namespace

uint8_t PhotonSpread::of(uint32_t units, uint32_t photons) {
    if (photons == 0 || photons >= kMostSpreadPhotons) return kUnknown;
    return code(static_cast<double>(units) / (static_cast<double>(photons) * kUnitsPerPhoton));
}

uint8_t PhotonSpread::code(double mean) { return static_cast<uint8_t>(std::lround(std::clamp(mean, 0.0, 1.0) * 254.0)); }

float balancedRadiusSquared(float r2, float n, float beta) {
    const double b2 = static_cast<double>(beta) * beta;
    if (!(b2 > 0) || !(n > 0)) return std::numeric_limits<float>::infinity();
    return static_cast<float>(std::cbrt(32.0 * r2 / (static_cast<double>(n) * b2)));
}

void AdaptiveRadius::add(size_t pixel, uint32_t m, uint8_t spread, float r2) {
    if (m == 0 || spread == PhotonSpread::kUnknown || !(r2 > 0)) return;
    Moments& mo = moments_[pixel];
    const float photons = static_cast<float>(m);
    mo.laplacian += photons * relativeLaplacian(PhotonSpread::mean(spread), r2);
    mo.photons += photons;
}

float AdaptiveRadius::shrink(size_t pixel, float n, float m, float r2, float alpha) const {
    const float scheduled = (n + alpha * m) / (n + m), fastest = (n + 0.5f * alpha * m) / (n + m);
    // The pixel and its eight neighbours, whose discs overlap its own: one pixel's photons
    // give a Laplacian too noisy to steer by for many passes.
    double laplacian = 0, photons = 0;
    forNeighbourhood(pixel, width_, height_, [&](size_t j) {
        laplacian += moments_[j].laplacian, photons += moments_[j].photons;
    });
    if (photons < kWarmUpPhotons) return scheduled;
    const auto beta = static_cast<float>(laplacian / photons);
    const float balanced = balancedRadiusSquared(r2, n + m, beta) / r2;
    return std::clamp(balanced, fastest, 1.0f);
}

void AdaptiveRadius::save(std::ostream& out) const {
    writeRaw(out, &kRadiusTag, 1);
    writeRaw(out, moments_.data(), moments_.size());
}

void AdaptiveRadius::restore(std::istream& in) {
    if (!readBlockTag(in, kRadiusTag)) {
        // Written before the block existed (or with fixed schedules): the moments start anew.
        std::fill(moments_.begin(), moments_.end(), Moments{});
        return;
    }
    std::vector<Moments> moments(moments_.size());
    readRaw(in, moments.data(), moments.size());
    for (const Moments& mo : moments)
        if (!std::isfinite(mo.laplacian) || !isFiniteNonNegative(mo.photons))
            throw CheckpointError("checkpoint: invalid radius moments");
    moments_ = std::move(moments);
}

}  // namespace photon
