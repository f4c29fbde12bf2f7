#include "light_sampler.h"
#include <algorithm>

namespace photon {

LightSampler::LightSampler(std::vector<const Light*> lights) : lights_(std::move(lights)) {
    double sum = 0;
    for (const Light* l : lights_) {
        sum += average(l->power());
        cdf_.push_back(static_cast<float>(sum));
    }
    totalAveragePower_ = static_cast<float>(sum);
    for (float& c : cdf_) c = sum > 0 ? static_cast<float>(c / sum) : 0.0f;
    if (!cdf_.empty()) cdf_.back() = 1.0f;
}

LightSampler::Pick LightSampler::pick(float u) const {
    if (lights_.empty() || totalAveragePower_ <= 0) return {};
    size_t i = static_cast<size_t>(std::upper_bound(cdf_.begin(), cdf_.end(), u) - cdf_.begin());
    i = std::min(i, lights_.size() - 1);
    return {lights_[i], probability(i), i};
}

}  // namespace photon
