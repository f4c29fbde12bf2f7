#include <photon/image_resize.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace photon {

ImageSize fitWithin(ImageSize image, ImageSize box) {
    if (image.width <= 0 || image.height <= 0 || box.width <= 0 || box.height <= 0) return image;
    if (box.width >= image.width && box.height >= image.height) return image;
    // Compare box.width / image.width with box.height / image.height without rounding.
    const int64_t w = image.width, h = image.height;
    auto clampSide = [](int64_t v, int hi) { return static_cast<int>(std::clamp<int64_t>(v, 1, hi)); };
    if (box.width * h <= box.height * w) {
        int width = std::min(box.width, image.width);
        return {width, clampSide((h * width + w / 2) / w, std::min(box.height, image.height))};
    }
    int height = std::min(box.height, image.height);
    return {clampSide((w * height + h / 2) / h, std::min(box.width, image.width)), height};
}

namespace {

// The filter: the cubic B-spline (B = 1, C = 0 in Mitchell and Netravali, "Reconstruction
// Filters in Computer Graphics", SIGGRAPH 1988), 4 target pixels wide. It is positive
// everywhere, and its copies one target pixel apart sum to 1, so each feature keeps its
// light: a one-pixel light 10^4 times the floor keeps its energy within 0.3% at any ratio
// and phase, where Blackman-Harris is off by up to 6% and a Gaussian by 11%. OpenImageIO's
// default for shrinking, Lanczos-3, has negative lobes that ring around such a light into
// negative radiance (-100 beside a light of 1000 on a floor of 0.1).
constexpr const char* kFilter = "bspline";
constexpr float kFilterWidth = 4;  // in target pixels

// Index `i` reflected into [0, n) about the image's edges (half-sample symmetric:
// ... 1 0 | 0 1 2 ... n-1 | n-1 n-2 ...), however far outside it lies.
int mirror(int i, int n) {
    int period = 2 * n, m = ((i % period) + period) % period;
    return m < n ? m : period - 1 - m;
}

// The image with a mirrored border of `padX`, `padY` pixels as data outside its display
// window (OpenImageIO reads it as overscan). A filter cut off at the edge and renormalised
// weighs the pixels near the edge less than the others (a light on the border of the
// Cornell box lost 2.7% of a 16x8 thumbnail's mean); over the mirror every pixel weighs
// the same, and the mean is kept exactly.
OIIO::ImageBuf withMirroredBorder(const Image& image, int padX, int padY) {
    OIIO::ImageSpec spec(image.width + 2 * padX, image.height + 2 * padY, 3, OIIO::TypeDesc::FLOAT);
    spec.x = -padX;
    spec.y = -padY;
    spec.full_x = spec.full_y = 0;
    spec.full_width = image.width;
    spec.full_height = image.height;
    OIIO::ImageBuf padded(spec);
    std::vector<float> row(static_cast<size_t>(spec.width) * 3);
    for (int y = -padY; y < image.height + padY; ++y) {
        const float* source = &image.rgb[static_cast<size_t>(mirror(y, image.height)) * image.width * 3];
        for (int x = -padX; x < image.width + padX; ++x) {
            const float* pixel = source + 3 * static_cast<size_t>(mirror(x, image.width));
            std::copy(pixel, pixel + 3, &row[3 * static_cast<size_t>(x + padX)]);
        }
        padded.set_pixels(OIIO::ROI(-padX, image.width + padX, y, y + 1), OIIO::TypeDesc::FLOAT, row.data());
    }
    return padded;
}

}  // namespace

Image resizeImage(const Image& image, ImageSize size) {
    if (size.width < 1 || size.height < 1 || size.width > image.width || size.height > image.height)
        throw std::invalid_argument("cannot resize a " + std::to_string(image.width) + "x" +
                                    std::to_string(image.height) + " image to " + std::to_string(size.width) +
                                    "x" + std::to_string(size.height));
    if (size == ImageSize{image.width, image.height}) return image;
    // The filter's half width in source pixels, and one more for rounding.
    auto pad = [](int from, int to) { return static_cast<int>(std::ceil(kFilterWidth / 2 * from / to)) + 1; };
    OIIO::ImageBuf source = withMirroredBorder(image, pad(image.width, size.width), pad(image.height, size.height));
    Image out(size.width, size.height);
    OIIO::ImageBuf target(OIIO::ImageSpec(size.width, size.height, 3, OIIO::TypeDesc::FLOAT), out.rgb.data());
    if (!OIIO::ImageBufAlgo::resize(target, source, kFilter, kFilterWidth))
        throw std::runtime_error("cannot resize the image: " + target.geterror());
    return out;
}

LayeredImage resizeImage(const LayeredImage& image, ImageSize size) {
    LayeredImage out{resizeImage(image.main, size), {}};
    for (const ImageLayer& layer : image.layers)
        out.layers.push_back({layer.name, layer.channels, resizeImage(layer.image, size)});
    return out;
}

}  // namespace photon
