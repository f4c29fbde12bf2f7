// Writing images through OpenImageIO: linear EXR, tone-mapped PNG.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>
#include "image.h"

namespace photon {

// Exposure scaling by 2^exposure, then clamping and the sRGB transfer curve (IEC 61966-2-1).
std::vector<uint8_t> toneMapToSrgb8(const Image& image, float exposure);

// Throw std::runtime_error with OpenImageIO's message on failure.
void writeExr(const Image& image, const std::filesystem::path& file);
void writePng(const Image& image, const std::filesystem::path& file, float exposure);
// In-memory encodings, for callers that serve images rather than store them.
std::vector<uint8_t> encodePng(const Image& image, float exposure);
std::vector<uint8_t> encodeExr(const Image& image);
// Reads any image OpenImageIO knows into linear floats as stored (no colour conversion).
Image readImage(const std::filesystem::path& file);

}  // namespace photon
