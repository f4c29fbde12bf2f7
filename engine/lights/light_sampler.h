// Picks a light with probability proportional to its power: the rule for emitting
// photons (flux stays equal across lights), and for shadow rays with render.light_sampler
// "power" (direct_light_sampler.h).
#pragma once
#include <algorithm>
#include <vector>
#include "lights/light.h"

namespace photon {

class LightSampler {
public:
    LightSampler() = default;
    explicit LightSampler(std::vector<const Light*> lights);

    struct Pick {
        const Light* light = nullptr;
        float probability = 0;
        size_t index = 0;  // position of the light in the list the sampler was made from
    };
    // Inline: every photon and every shadow ray picks a light.
    Pick pick(float u) const {
        if (lights_.empty() || totalAveragePower_ <= 0) return {};
        size_t i = lights_.size() == 1 ? 0 : static_cast<size_t>(std::upper_bound(cdf_.begin(), cdf_.end(), u) - cdf_.begin());
        i = std::min(i, lights_.size() - 1);
        return {lights_[i], probability(i), i};
    }
    size_t size() const { return lights_.size(); }
    const Light& light(size_t i) const { return *lights_[i]; }
    // The probability with which pick() returns light i.
    float probability(size_t i) const { return cdf_[i] - (i == 0 ? 0.0f : cdf_[i - 1]); }
    // Mean over channels of the summed power: the unit photon fluxes are expressed in.
    float totalAveragePower() const { return totalAveragePower_; }

private:
    std::vector<const Light*> lights_;
    std::vector<float> cdf_;
    float totalAveragePower_ = 0;
};

}  // namespace photon
