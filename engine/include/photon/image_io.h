// Writing images through OpenImageIO: linear EXR (with any extra layers as more channels
// of the one part), tone-mapped PNG (the main image only), in memory or to files.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>
#include <photon/image.h>
#include <photon/pending_image.h>

namespace photon {

// Exposure scaling by 2^exposure, then clamping and the sRGB transfer curve (IEC 61966-2-1).
std::vector<uint8_t> toneMapToSrgb8(const Image& image, float exposure);

// Throw std::runtime_error with OpenImageIO's message on failure.
void writeExr(const Image& image, const std::filesystem::path& file);
// Channels R, G, B (the main image) first, then each layer's "<name>.<channel>".
void writeExr(const LayeredImage& image, const std::filesystem::path& file);
void writePng(const Image& image, const std::filesystem::path& file, float exposure);
// In-memory encodings, for callers that serve images rather than store them.
std::vector<uint8_t> encodePng(const Image& image, float exposure);
std::vector<uint8_t> encodeExr(const Image& image);
std::vector<uint8_t> encodeExr(const LayeredImage& image);
// A render's image as the scene asks for it: the PNG tone-mapped with the scene's exposure
// (the main image), the EXR linear with every layer.
std::vector<uint8_t> encodePng(const PendingImage& image);
std::vector<uint8_t> encodeExr(const PendingImage& image);
void writePng(const PendingImage& image, const std::filesystem::path& file);
void writeExr(const PendingImage& image, const std::filesystem::path& file);
// Reads any image OpenImageIO knows into linear floats as stored (no colour conversion):
// its first three channels (R, G, B of the files written above).
Image readImage(const std::filesystem::path& file);
// The three channels "<prefix>R", "<prefix>G", "<prefix>B" (or other names) of a file;
// throws std::runtime_error if one is missing.
Image readImageChannels(const std::filesystem::path& file, const std::array<std::string, 3>& channels);

}  // namespace photon
