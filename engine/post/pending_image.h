// A pass's image whose post filter runs when it is first asked for, not when the pass
// ends: a service that keeps every pass's image pays for denoising only for the images
// someone looks at (the filter can cost as much as a pass).
#pragma once
#include <memory>
#include <mutex>
#include "../film/image_layers.h"
#include "denoiser.h"

namespace photon {

class PendingImage {
public:
    // `denoiser` may be null: the raw image is then the main one, with no layers.
    PendingImage(Image raw, std::shared_ptr<const Denoiser> denoiser)
        : raw_(std::move(raw)), denoiser_(std::move(denoiser)) {}

    // The filtered image with its layers (Denoiser::layers); computed once, thread-safe.
    const LayeredImage& layers() const {
        std::call_once(once_, [&] {
            layers_ = denoiser_ ? denoiser_->layers(std::move(raw_)) : LayeredImage{std::move(raw_), {}};
        });
        return layers_;
    }

private:
    mutable Image raw_;  // moved into layers_ on first use
    std::shared_ptr<const Denoiser> denoiser_;
    mutable std::once_flag once_;
    mutable LayeredImage layers_;
};

}  // namespace photon
