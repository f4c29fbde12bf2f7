// A pass's image whose post filter runs when it is first asked for, not when the pass
// ends: a service that keeps every pass's image pays for denoising only for the images
// someone looks at (the filter can cost as much as a pass). It carries the scene's
// exposure, so whoever encodes it (image_io.h) tone-maps it as the scene asks.
#pragma once
#include <memory>
#include <mutex>
#include <photon/image.h>

namespace photon {

class Denoiser;
struct PixelErrors;

class PendingImage {
public:
    // `denoiser` may be null: the raw image is then the main one, with no denoiser layers.
    // `errors`, when given, adds the error heat map of the raw image as the layer "error".
    PendingImage(Image raw, std::shared_ptr<const Denoiser> denoiser, float exposure,
                 std::shared_ptr<const PixelErrors> errors = nullptr);
    ~PendingImage();

    // The filtered image with its layers (the denoiser's raw and guide buffers); computed
    // once, thread-safe.
    const LayeredImage& layers() const;
    // Stops (2^exposure) applied when the image is tone-mapped to 8 bits.
    float exposure() const { return exposure_; }

private:
    mutable Image raw_;  // moved into layers_ on first use
    std::shared_ptr<const Denoiser> denoiser_;
    std::shared_ptr<const PixelErrors> errors_;
    float exposure_ = 0;
    mutable std::once_flag once_;
    mutable LayeredImage layers_;
};

}  // namespace photon
