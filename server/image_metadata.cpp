#include "image_metadata.h"
#include <array>
#include <charconv>

namespace photon::server {

namespace {

constexpr std::array kKeys{metadata_keys::kSoftware,      metadata_keys::kIntegrator, metadata_keys::kPasses,
                           metadata_keys::kPhotonsTraced, metadata_keys::kSeed,       metadata_keys::kElapsedSeconds,
                           metadata_keys::kExposure};

template <typename T>
std::string shortest(T value) {
    std::array<char, 64> buffer;
    auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return ec == std::errc() ? std::string(buffer.data(), end) : std::string();
}

}  // namespace

std::string softwareName() { return std::string("photon ") + PHOTON_VERSION; }

std::string metadataNumber(double value) { return shortest(value); }
std::string metadataNumber(float value) { return shortest(value); }

ImageMetadata passMetadata(const JobSettings& settings, const JobProgress& progress, float exposure) {
    using namespace metadata_keys;
    return {
        {kSoftware, softwareName()},
        {kIntegrator, settings.integrator},
        {kPasses, std::to_string(progress.pass)},
        {kPhotonsTraced, std::to_string(progress.photonsTraced)},
        {kSeed, std::to_string(settings.seed)},
        {kElapsedSeconds, metadataNumber(progress.elapsedSeconds)},
        {kExposure, metadataNumber(exposure)},
    };
}

std::optional<std::string> metadataValue(const ImageMetadata& metadata, const std::string& key) {
    for (const auto& [k, v] : metadata)
        if (k == key) return v;
    return std::nullopt;
}

void setMetadataValue(ImageMetadata& metadata, const std::string& key, const std::string& value) {
    for (auto& [k, v] : metadata)
        if (k == key) {
            v = value;
            return;
        }
    metadata.emplace_back(key, value);
}

ImageMetadata renderMetadataOf(const ImageMetadata& metadata) {
    ImageMetadata out;
    for (const char* key : kKeys)
        if (std::optional<std::string> value = metadataValue(metadata, key)) out.emplace_back(key, *value);
    return out;
}

}  // namespace photon::server
