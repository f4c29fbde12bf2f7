#include <photon/pending_image.h>
#include "film/pixel_errors.h"
#include "post/denoiser.h"

namespace photon {

PendingImage::PendingImage(Image raw, std::shared_ptr<const Denoiser> denoiser, float exposure,
                           std::shared_ptr<const PixelErrors> errors)
    : raw_(std::move(raw)), denoiser_(std::move(denoiser)), errors_(std::move(errors)), exposure_(exposure) {}

PendingImage::~PendingImage() = default;

const LayeredImage& PendingImage::layers() const {
    std::call_once(once_, [&] {
        layers_ = denoiser_ ? denoiser_->layers(std::move(raw_)) : LayeredImage{std::move(raw_), {}};
        if (errors_) layers_.layers.push_back(errorLayer(*errors_));
    });
    return layers_;
}

}  // namespace photon
