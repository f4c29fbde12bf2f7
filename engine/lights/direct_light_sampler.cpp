#include "lights/direct_light_sampler.h"
#include <algorithm>

namespace photon {

DirectLightSampler::DirectLightSampler(const LightSampler& byPower, LightSamplerKind kind)
    : byPower_(&byPower), kind_(kind) {
    finiteSlot_.assign(byPower.size(), -1);
    std::vector<LightBounds> bounds;
    double finitePower = 0, infinitePower = 0;
    std::vector<double> infiniteSums;
    for (size_t i = 0; i < byPower.size(); ++i) {
        const double power = byPower.probability(i);
        if (!byPower.light(i).sampledDirectly()) {
            unsampled_ = true;  // never picked here (Light::sampledDirectly)
            continue;
        }
        if (std::optional<LightBounds> b = byPower.light(i).bounds()) {
            finiteSlot_[i] = static_cast<int32_t>(bounds.size());
            bounds.push_back(*b);
            finiteLight_.push_back(static_cast<uint32_t>(i));
            finitePower += power;
        } else {
            infinite_.push_back(static_cast<uint32_t>(i));
            infinitePower += power;
            infiniteSums.push_back(infinitePower);
        }
    }
    for (double s : infiniteSums) infiniteCdf_.push_back(static_cast<float>(s / infinitePower));
    if (!infiniteCdf_.empty()) infiniteCdf_.back() = 1.0f;
    infinitePower_ = infinitePower;
    finiteShare_ = infinite_.empty() ? 1.0f : static_cast<float>(finitePower / (finitePower + infinitePower));
    finite_ = LightImportances(bounds);
    if (finite_.size() > kMaxExhaustive) tree_ = LightTree(bounds);
}

float DirectLightSampler::infiniteProbability(size_t i) const {
    // Their share, by power among themselves; the power sampler's own figure where every
    // light is sampled (the same, to the bit, as it has always been).
    if (!unsampled_) return byPower_->probability(i);
    return static_cast<float>((1.0 - finiteShare_) * byPower_->probability(i) / infinitePower_);
}

float DirectLightSampler::importances(Vec3 p, Vec3 n, float* out) const {
    return finite_.evaluate(0, finite_.size(), p, n, out);
}

LightSampler::Pick DirectLightSampler::pick(float u, Vec3 p, Vec3 n) const {
    if (!spatial()) return byPower_->pick(u);
    if (u >= finiteShare_) {
        // An infinite light, by power among them (finiteShare_ < 1 here).
        const float v = (u - finiteShare_) / (1.0f - finiteShare_);
        size_t k = static_cast<size_t>(std::upper_bound(infiniteCdf_.begin(), infiniteCdf_.end(), v) - infiniteCdf_.begin());
        k = std::min(k, infinite_.size() - 1);
        const uint32_t i = infinite_[k];
        return {&byPower_->light(i), infiniteProbability(i), i};
    }
    const float v = std::min(u / finiteShare_, 0.99999994f);
    if (!tree_.empty()) {
        LightTree::Pick t = tree_.pick(v, p, n);
        if (!(t.probability > 0)) return {};
        const uint32_t i = finiteLight_[t.light];
        return {&byPower_->light(i), finiteShare_ * t.probability, i};
    }
    float each[kMaxExhaustive];
    const float sum = importances(p, n, each);
    if (!(sum > 0)) return {};
    const float target = v * sum;
    float below = 0;
    size_t k = 0;
    // The last light with importance takes what rounding leaves past the end.
    size_t last = 0;
    for (size_t j = 0; j < finite_.size(); ++j)
        if (each[j] > 0) last = j;
    while (k < last && (!(each[k] > 0) || target >= below + each[k])) below += each[k++];
    const uint32_t i = finiteLight_[k];
    return {&byPower_->light(i), finiteShare_ * (each[k] / sum), i};
}

float DirectLightSampler::probability(size_t i, Vec3 p, Vec3 n) const {
    if (!spatial()) return byPower_->probability(i);
    const int32_t slot = finiteSlot_[i];
    if (slot < 0) return byPower_->light(i).sampledDirectly() ? infiniteProbability(i) : 0.0f;
    if (!tree_.empty()) return finiteShare_ * tree_.probability(static_cast<uint32_t>(slot), p, n);
    float each[kMaxExhaustive];
    const float sum = importances(p, n, each);
    return sum > 0 ? finiteShare_ * (each[slot] / sum) : 0.0f;
}

}  // namespace photon
