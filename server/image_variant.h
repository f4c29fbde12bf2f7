// Encodings of a job's image other than the two cached per pass: the PNG at another
// exposure, and smaller copies (thumbnails) in either format. They are made per request
// and not kept, so any number of exposures and sizes costs no memory between requests.
// Each is made from the pass's EXR (cached per pass, or on disk once the job finished):
// the one encoding that holds all a variant needs, the linear image with every layer, and
// the render's metadata with the scene's exposure.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <photon/image_resize.h>
#include "image_format.h"

namespace photon::server {

// Exposures a client may ask for, in stops: a factor of about a million either way, far
// beyond any useful view (an 8-bit sRGB PNG spans about 12 stops from its darkest step to
// white), so no view is lost; and a bound keeps 2^exposure an ordinary float.
inline constexpr double kMinExposure = -20, kMaxExposure = 20;
// The largest box side a client may ask for; a box larger than the render is not an error
// (the image is never enlarged), this only keeps the arithmetic and the names bounded.
inline constexpr int kMaxBoxSide = 65536;

struct ImageVariant {
    std::optional<float> exposure;  // PNG only: stops instead of the scene's
    std::optional<ImageSize> size;  // smaller than the render in at least one side
    bool raw = false;               // the "raw" layer (before the denoiser) as the image
    bool errorMap = false;          // PNG only: the error heat map (photon/error_map.h) as the image
    bool isDefault() const { return !exposure && !size && !raw && !errorMap; }
};

// The variant asked for with `box` (or none) for a render of `render`'s size: no size when
// the box does not make it smaller, so that such a request is the plain image.
ImageVariant variantFor(std::optional<float> exposure, std::optional<ImageSize> box, ImageSize render,
                        bool raw = false, bool errorMap = false);

// What tells the variant apart in ETags and file names: "" for the default, else e.g.
// "-raw", "-error", "-256x192", "-ev1.5", "-raw-256x192-ev-2" (the exposure in its shortest exact form, so
// "1", "1.0" and "1e0" name one entity).
std::string variantSuffix(const ImageVariant& variant);

// `exr`: the EXR encoding of a pass as the image cache makes it. Throws std::runtime_error
// for bytes that are no such image, or that have no raw layer when the variant asks for it;
// ServiceError (NotFound) for an error map of a pass without an error estimate.
std::shared_ptr<const std::string> encodeVariant(const std::string& exr, ImageFormat format,
                                                 const ImageVariant& variant);

}  // namespace photon::server
