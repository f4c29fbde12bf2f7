// The text a served image carries about its render (PNG tEXt chunks, EXR header
// attributes): which program made it, with which integrator and seed, and how far it got.
// Read back with any OpenImageIO tool, e.g. `oiiotool --info -v image.exr`.
#pragma once
#include <optional>
#include <string>
#include <photon/image_io.h>
#include "job.h"

namespace photon::server {

namespace metadata_keys {
inline constexpr const char* kSoftware = "Software";  // the name TIFF, EXIF and PNG use
inline constexpr const char* kIntegrator = "photon:integrator";
inline constexpr const char* kPasses = "photon:passes";
inline constexpr const char* kPhotonsTraced = "photon:photons_traced";
inline constexpr const char* kSeed = "photon:seed";
inline constexpr const char* kElapsedSeconds = "photon:elapsed_seconds";
// The exposure in stops the PNG was tone-mapped with; in an EXR (linear), the scene's.
inline constexpr const char* kExposure = "photon:exposure";
}  // namespace metadata_keys

// "photon <version>", the version being the project's (CMake's PROJECT_VERSION).
std::string softwareName();

// The metadata of the image after the pass `progress` describes.
ImageMetadata passMetadata(const JobSettings& settings, const JobProgress& progress, float exposure);

// Numbers as text that reads back to the same value (shortest round-trip form).
std::string metadataNumber(double value);
std::string metadataNumber(float value);

std::optional<std::string> metadataValue(const ImageMetadata& metadata, const std::string& key);
// Replaces the key's value, or adds the key.
void setMetadataValue(ImageMetadata& metadata, const std::string& key, const std::string& value);
// Only the keys above, in their order: what a re-encoding takes over from a decoded file
// (whose header also holds the codec's own attributes, e.g. "compression").
ImageMetadata renderMetadataOf(const ImageMetadata& metadata);

}  // namespace photon::server
