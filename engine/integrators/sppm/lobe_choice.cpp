#include "integrators/sppm/lobe_choice.h"
#include <algorithm>
#include <cmath>
#include "integrators/common/checkpoint.h"
#include "integrators/sppm/pixel_neighbourhood.h"
#include "math/bfloat16.h"

namespace photon {

namespace {
// Marks the block in a checkpoint: no pass count of the halves that may follow instead
// (PassHalves, an int64 below 2^31) can equal it.
constexpr uint64_t kBlockTag = 0x45434f4843424f4cull;  // "LOBCHOCE"
// Neither branch's weight beyond 20. A ceiling of 0.5 instead of 0.95 left the coated box's
// noise at 0.071 instead of 0.064 (512 x 512, 10 s).
constexpr float kMinProbability = 0.05f, kMaxProbability = 0.95f;
}  // namespace

LobeChoiceRecord LobeChoiceRecord::of(bool others, float probability, float directBefore) {
    // At least 1 in 15 bits: a choice made is never read as none.
    const auto q = static_cast<uint16_t>(std::clamp(std::lround(probability * 32767.0f), 1l, 32767l));
    return {static_cast<uint16_t>(q | (others ? 0x8000u : 0u)), toBfloat16(directBefore)};
}

float LobeChoiceRecord::directBeforeChoice() const { return fromBfloat16(directBefore); }

float LearnedLobeChoice::othersProbability(size_t pixel, float materialOthers) const {
    if (passes_ < kWarmUpPasses || !(materialOthers > 0 && materialOthers < 1)) return materialOthers;
    double others = 0, base = 0;
    // The pixel and its eight neighbours: measured on the coated box at 512 x 512 (10 s,
    // adaptive photons), relative noise in luminance 0.078 from the pixel alone, 0.064 from
    // 3 x 3, 0.066 from 5 x 5.
    forNeighbourhood(pixel, width_, height_, [&](size_t j) { others += moments_[j].others, base += moments_[j].base; });
    if (!(others + base > 0)) return materialOthers;
    const double a = std::sqrt(others), b = std::sqrt(base);
    const float learned = static_cast<float>(a / (a + b));
    const float lo = std::max(kMinProbability, 0.5f * materialOthers);
    const float hi = std::max(kMaxProbability, materialOthers);
    return std::clamp(learned, lo, hi);
}

void LearnedLobeChoice::save(std::ostream& out) const {
    writeRaw(out, &kBlockTag, 1);
    writeRaw(out, &passes_, 1);
    writeRaw(out, moments_.data(), moments_.size());
}

void LearnedLobeChoice::restore(std::istream& in, int64_t renderPasses) {
    if (!readBlockTag(in, kBlockTag)) {
        // Written before the block existed: what follows is another block's. Learning
        // starts anew.
        passes_ = 0;
        std::fill(moments_.begin(), moments_.end(), Moments{});
        return;
    }
    int64_t passes = 0;
    readRaw(in, &passes, 1);
    if (passes < 0 || passes > renderPasses) throw CheckpointError("checkpoint: invalid lobe choice");
    std::vector<Moments> moments(moments_.size());
    readRaw(in, moments.data(), moments.size());
    for (const Moments& m : moments)
        if (!(m.others >= 0 && m.base >= 0 && std::isfinite(m.others) && std::isfinite(m.base)))
            throw CheckpointError("checkpoint: invalid lobe choice");
    passes_ = passes;
    moments_ = std::move(moments);
}

}  // namespace photon
