// Smaller copies of images (thumbnails), resampled with a low-pass filter in linear light.
#pragma once
#include <photon/image.h>

namespace photon {

struct ImageSize {
    int width = 0, height = 0;
    bool operator==(const ImageSize&) const = default;
};

// The largest size within `box` with `image`'s aspect ratio, never larger than `image`:
// the side that limits is the box's, the other is rounded to the nearest pixel (at least 1,
// at most the box's). A box at least as large as the image gives the image's own size.
ImageSize fitWithin(ImageSize image, ImageSize box);

// The image resampled to `size` (each side at most the image's) with the cubic B-spline
// filter over the image mirrored at its edges, which keeps the mean and every small bright
// feature's light, at the edges too; every layer alike. Throws std::invalid_argument for a size it cannot make.
Image resizeImage(const Image& image, ImageSize size);
LayeredImage resizeImage(const LayeredImage& image, ImageSize size);

}  // namespace photon
