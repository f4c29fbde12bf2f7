// The encodings the service hands out: tone-mapped PNG for viewing, linear EXR for data.
#pragma once
#include <optional>
#include <string>

namespace photon::server {

enum class ImageFormat { Png, Exr };

inline const char* toString(ImageFormat f) { return f == ImageFormat::Png ? "png" : "exr"; }
inline const char* mimeType(ImageFormat f) { return f == ImageFormat::Png ? "image/png" : "image/x-exr"; }
inline std::optional<ImageFormat> parseImageFormat(const std::string& text) {
    if (text == "png") return ImageFormat::Png;
    if (text == "exr") return ImageFormat::Exr;
    return std::nullopt;
}

}  // namespace photon::server
