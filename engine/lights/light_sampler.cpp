#include "lights/light_sampler.h"
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

}  // namespace photon
