// Writing images through OpenImageIO: linear EXR (with any extra layers as more channels
// of the one part), tone-mapped PNG (the main image only), in memory or to files; and
// reading them back.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>
#include <photon/image.h>
#include <photon/pending_image.h>

namespace photon {

// Text the encoded file carries: PNG tEXt chunks and EXR string header attributes, each
// key as given (e.g. "Software", "photon:seed"). The engine writes what it is handed and
// adds nothing: it does not know whose render the image is.
using ImageMetadata = std::vector<std::pair<std::string, std::string>>;

// Exposure scaling by 2^exposure, then clamping and the sRGB transfer curve (IEC 61966-2-1).
std::vector<uint8_t> toneMapToSrgb8(const Image& image, float exposure);

// Throw std::runtime_error with OpenImageIO's message on failure.
void writeExr(const Image& image, const std::filesystem::path& file);
// Channels R, G, B (the main image) first, then each layer's "<name>.<channel>".
void writeExr(const LayeredImage& image, const std::filesystem::path& file);
void writePng(const Image& image, const std::filesystem::path& file, float exposure);
// In-memory encodings, for callers that serve images rather than store them.
std::vector<uint8_t> encodePng(const Image& image, float exposure, const ImageMetadata& metadata = {});
std::vector<uint8_t> encodeExr(const Image& image);
std::vector<uint8_t> encodeExr(const LayeredImage& image, const ImageMetadata& metadata = {});
// A render's image as the scene asks for it: the PNG tone-mapped with the scene's exposure
// (the main image), the EXR linear with every layer.
std::vector<uint8_t> encodePng(const PendingImage& image, const ImageMetadata& metadata = {});
std::vector<uint8_t> encodeExr(const PendingImage& image, const ImageMetadata& metadata = {});
void writePng(const PendingImage& image, const std::filesystem::path& file);
void writeExr(const PendingImage& image, const std::filesystem::path& file);
// Reads any image OpenImageIO knows into linear floats as stored (no colour conversion):
// its first three channels (R, G, B of the files written above).
Image readImage(const std::filesystem::path& file);
// The three channels "<prefix>R", "<prefix>G", "<prefix>B" (or other names) of a file;
// throws std::runtime_error if one is missing.
Image readImageChannels(const std::filesystem::path& file, const std::array<std::string, 3>& channels);

// An encoded image read back from memory: its channels as stored (8-bit PNG values as
// value/255, no colour conversion), the first three as the main image and every further
// "<name>.<a>", "<name>.<b>", "<name>.<c>" triple as a layer, in the file's order (OpenEXR
// sorts layers by name; channels in no such triple are dropped), and every string
// attribute of its header (OpenImageIO's own among them, e.g. "compression").
struct DecodedImage {
    LayeredImage image;
    ImageMetadata metadata;
};
// `extension` ("png", "exr") names the format. Throws std::runtime_error on bad bytes.
DecodedImage decodeImageBytes(std::string_view bytes, const std::string& extension);

}  // namespace photon
