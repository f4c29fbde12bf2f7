#include "image_variant.h"
#include <algorithm>
#include <charconv>
#include <stdexcept>
#include <photon/error_map.h>
#include <photon/image_io.h>
#include "errors.h"
#include "image_metadata.h"

namespace photon::server {

namespace {

// The scene's exposure as the EXR records it; an EXR without it (not written by this
// service) is shown as it is, at 0 stops.
float sceneExposure(const ImageMetadata& metadata) {
    std::optional<std::string> text = metadataValue(metadata, metadata_keys::kExposure);
    float value = 0;
    if (text) std::from_chars(text->data(), text->data() + text->size(), value);
    return value;
}

}  // namespace

ImageVariant variantFor(std::optional<float> exposure, std::optional<ImageSize> box, ImageSize render, bool raw,
                        bool errorMap) {
    ImageVariant variant{exposure, std::nullopt, raw, errorMap};
    if (box) {
        ImageSize fitted = fitWithin(render, *box);
        if (fitted != render) variant.size = fitted;
    }
    return variant;
}

std::string variantSuffix(const ImageVariant& variant) {
    // Appended piece by piece: GCC 12 warns (-Wrestrict, wrongly) about "-" + std::string.
    std::string suffix;
    if (variant.raw) suffix.append("-raw");
    if (variant.errorMap) suffix.append("-error");
    if (variant.size) {
        suffix.append("-").append(std::to_string(variant.size->width));
        suffix.append("x").append(std::to_string(variant.size->height));
    }
    if (variant.exposure) suffix.append("-ev").append(metadataNumber(*variant.exposure));
    return suffix;
}

std::shared_ptr<const std::string> encodeVariant(const std::string& exr, ImageFormat format,
                                                 const ImageVariant& variant) {
    DecodedImage decoded = decodeImageBytes(exr, "exr");
    if (variant.raw) {
        auto raw = std::find_if(decoded.image.layers.begin(), decoded.image.layers.end(),
                                [](const ImageLayer& layer) { return layer.name == "raw"; });
        if (raw == decoded.image.layers.end()) throw std::runtime_error("the image has no raw layer");
        decoded.image = LayeredImage{std::move(raw->image), {}};
    }
    // Resampled in linear light, before tone mapping: averaging sRGB codes would darken
    // every edge between light and dark.
    LayeredImage image = variant.size ? resizeImage(decoded.image, *variant.size) : std::move(decoded.image);
    ImageMetadata metadata = renderMetadataOf(decoded.metadata);
    std::vector<uint8_t> bytes;
    if (variant.errorMap) {  // a picture of its own: its colours are final, at exposure 0
        std::optional<Image> map = errorHeatMap(image);
        if (!map)
            throw ServiceError(ErrorKind::NotFound,
                               "this pass has no error estimate (its method keeps none, or it is the first pass)");
        setMetadataValue(metadata, metadata_keys::kExposure, metadataNumber(0.0f));
        bytes = encodePng(*map, 0.0f, metadata);
    } else if (format == ImageFormat::Png) {
        float exposure = variant.exposure.value_or(sceneExposure(metadata));
        setMetadataValue(metadata, metadata_keys::kExposure, metadataNumber(exposure));
        bytes = encodePng(image.main, exposure, metadata);
    } else {
        bytes = encodeExr(image, metadata);
    }
    return std::make_shared<const std::string>(bytes.begin(), bytes.end());
}

}  // namespace photon::server
