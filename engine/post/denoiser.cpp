#include "post/denoiser.h"
#include "post/bilateral.h"

namespace photon {

Denoiser::Denoiser(const Scene& scene, const DenoiseSettings& settings) : settings_(settings) {
    if (settings_.guide) features_ = renderFeatureBuffers(scene, settings_.featureSamples);
}

Image Denoiser::apply(const Image& raw) const {
    BilateralParams params{settings_.sigmaSpatial, settings_.sigmaRange, settings_.sigmaAlbedo, settings_.sigmaNormal};
    BilateralGuides guides;
    if (settings_.guide) guides = {&features_.albedo, &features_.normal};
    return bilateralFilter(raw, params, guides);
}

LayeredImage Denoiser::layers(Image raw) const {
    LayeredImage out{apply(raw), {}};
    out.layers.push_back({"raw", {"R", "G", "B"}, std::move(raw)});
    if (settings_.guide) {
        out.layers.push_back({"albedo", {"R", "G", "B"}, features_.albedo});
        out.layers.push_back({"normal", {"X", "Y", "Z"}, features_.normal});
    }
    return out;
}

}  // namespace photon
