// SPPM's photon guiding: the training passes that teach the emission guide where photons
// reach visible points (integrators/common/emission_guide.h).
#include <algorithm>
#include <cmath>
#include "integrators/sppm/sppm.h"

namespace photon {

bool SppmIntegrator::trainGuide(const CancelToken& cancel) {
    const int64_t pass = passIndex_;
    const float shrink = globalShrink_;
    guidePhotons_.assign(static_cast<size_t>(width_) * height_, 0);
    emitter_.setGuide(&*guide_);
    bool trained = true;
    for (guidePass_ = 0; guidePass_ < kGuidePasses && trained; ++guidePass_) {
        // Random streams of their own: pass indices below 0, which no pass uses.
        passIndex_ = -1 - guidePass_;
        globalShrink_ = 1;  // the global schedule's first radius
        // The first training pass only counts photons; the others' worth adds up over bands.
        for (std::vector<uint64_t>& worth : guideWorth_) std::fill(worth.begin(), worth.end(), 0);
        // A pixel's count is read by its own camera path alone (guideWeight), in the next
        // pass, so each band's go in as it ends.
        trained = traceBands(
            cancel, guidePhotonsPerPass(),
            [&](int first, int end, bool) {
                for (size_t i = static_cast<size_t>(first) * width_; i < static_cast<size_t>(end) * width_; ++i)
                    guidePhotons_[i] += result(i).photonCount;
            },
            false);
        if (!trained) break;
        if (guidePass_ > 0) teachGuide();
    }
    guidePass_ = -1;
    passIndex_ = pass;
    globalShrink_ = shrink;
    guidePhotons_ = decltype(guidePhotons_)();  // frees its storage (= {} would only clear it)
    // Cancelled: the guide starts again from nothing next time, as a resumed render's does.
    if (!trained) guide_.emplace(scene_->lights());
    return trained;
}

int64_t SppmIntegrator::guidePhotonsPerPass() const {
    return std::max<int64_t>(settings_.photonsPerPass, 256 * static_cast<int64_t>(guide_->cellCount()));
}

uint32_t SppmIntegrator::guideWeight(size_t index) const {
    const float meanPhotons = guidePass_ > 0 ? static_cast<float>(guidePhotons_[index]) / static_cast<float>(guidePass_) : 0.0f;
    return static_cast<uint32_t>(std::lround(65536.0f / (1.0f + meanPhotons)));
}

void SppmIntegrator::teachGuide() {
    std::vector<uint64_t> worth(guide_->cellCount(), 0);
    for (const std::vector<uint64_t>& local : guideWorth_)
        for (size_t c = 0; c < local.size(); ++c) worth[c] += local[c];
    guide_->learn(worth, guidePhotonsPerPass());
}

}  // namespace photon
