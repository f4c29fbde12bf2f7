// The form: "PHIM", a version, width and height (little-endian), then the R, G, B floats of
// each pixel, row by row, as zlib compresses them (film/zlib_block.h).
#include <photon/image_bytes.h>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include "film/zlib_block.h"

namespace photon {
namespace {

constexpr char kMagic[4] = {'P', 'H', 'I', 'M'};
constexpr uint32_t kVersion = 1;

struct Header {
    char magic[4];
    uint32_t version;
    int32_t width, height;
};

}  // namespace

std::string encodeImageBytes(const Image& image) {
    Header h{};
    std::memcpy(h.magic, kMagic, sizeof kMagic);
    h.version = kVersion;
    h.width = image.width, h.height = image.height;
    return packZlibBlock(std::string_view(reinterpret_cast<const char*>(&h), sizeof h), image.rgb.data(),
                         image.rgb.size() * sizeof(float));
}

Image decodeImageBytes(std::string_view bytes) {
    Header h;
    if (bytes.size() < sizeof h) throw std::invalid_argument("image bytes: shorter than their header");
    std::memcpy(&h, bytes.data(), sizeof h);
    if (std::memcmp(h.magic, kMagic, sizeof kMagic) != 0) throw std::invalid_argument("image bytes: not an image");
    if (h.version != kVersion)
        throw std::invalid_argument("image bytes: version " + std::to_string(h.version) + ", expected " +
                                    std::to_string(kVersion));
    if (h.width <= 0 || h.height <= 0 || int64_t(h.width) * h.height > (int64_t(1) << 28))
        throw std::invalid_argument("image bytes: invalid size");
    Image image(h.width, h.height);
    if (!unpackZlibBlock(bytes, sizeof h, image.rgb.data(), image.rgb.size() * sizeof(float)))
        throw std::invalid_argument("image bytes: damaged pixels");
    return image;
}

}  // namespace photon
