// The denoising post filter of render.denoise (docs/denoise.md): the scene's feature
// buffers, computed once, and the bilateral filter applied to any snapshot.
#pragma once
#include <photon/image.h>
#include <photon/render_settings.h>
#include "post/feature_buffers.h"

namespace photon {

class Denoiser {
public:
    // Traces the feature buffers (settings.featureSamples rays per pixel) when guided.
    Denoiser(const Scene& scene, const DenoiseSettings& settings);

    Image apply(const Image& raw) const;
    // The denoised image as the main one, with layers "raw" and, when guided, "albedo"
    // and "normal".
    LayeredImage layers(Image raw) const;
    const FeatureBuffers& features() const { return features_; }

private:
    DenoiseSettings settings_;
    FeatureBuffers features_;  // empty images when not guided
};

}  // namespace photon
