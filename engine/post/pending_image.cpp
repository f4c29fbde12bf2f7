#include <photon/pending_image.h>
#include <optional>
#include "film/pixel_errors.h"
#include "post/denoiser.h"

namespace photon {

PendingImage::PendingImage(Image raw, std::shared_ptr<const Denoiser> denoiser, float exposure,
                           std::shared_ptr<const PixelErrors> errors)
    : raw_(std::move(raw)), denoiser_(std::move(denoiser)), errors_(std::move(errors)), exposure_(exposure) {}

PendingImage::~PendingImage() = default;

const LayeredImage& PendingImage::layers() const {
    std::call_once(once_, [&] {
        std::optional<ImageLayer> error;
        if (errors_) error = errorLayer(*errors_, raw_);
        layers_ = denoiser_ ? denoiser_->layers(std::move(raw_)) : LayeredImage{std::move(raw_), {}};
        if (error) layers_.layers.push_back(std::move(*error));
    });
    return layers_;
}

}  // namespace photon
