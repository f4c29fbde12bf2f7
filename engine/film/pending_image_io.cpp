// A render's image encoded as its scene asks: the exposure travels with the image, so no
// caller has to fetch it from the scene and hand it back.
#include <photon/image_io.h>

namespace photon {

std::vector<uint8_t> encodePng(const PendingImage& image, const ImageMetadata& metadata) {
    return encodePng(image.layers().main, image.exposure(), metadata);
}
std::vector<uint8_t> encodeExr(const PendingImage& image, const ImageMetadata& metadata) {
    return encodeExr(image.layers(), metadata);
}
void writePng(const PendingImage& image, const std::filesystem::path& file) {
    writePng(image.layers().main, file, image.exposure());
}
void writeExr(const PendingImage& image, const std::filesystem::path& file) { writeExr(image.layers(), file); }

}  // namespace photon
