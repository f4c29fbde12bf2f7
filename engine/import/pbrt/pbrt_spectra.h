// pbrt-v4's spectral values as the linear sRGB colours photon renders with: "rgb" as it is,
// "blackbody" temperatures, named spectra and sampled (wavelength, value) spectra projected
// the way scripts/metal_rgb.py projects the named metals' measurements.
#pragma once
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>
#include <photon/vec.h>
#include "import/pbrt/pbrt_parser.h"

namespace photon::pbrt {

// How pbrt-v4 reads a spectrum, which decides its normalisation: light spectra other than
// "rgb" are scaled to unit luminance (pbrt-v4 divides a light's scale by the spectrum's
// photometric value); reflectances and indices are taken as they are.
enum class SpectrumKind { Reflectance, Illuminant, Index };

// The colour of a parameter of type rgb, spectrum, blackbody, float or integer. Spectrum
// files (".spd") are read relative to `baseDir` and must stay inside it. Throws SceneError
// at the parameter's file:line for an unknown name or a malformed value.
Color spectrumColor(const Param& p, SpectrumKind kind, const std::filesystem::path& baseDir);

}  // namespace photon::pbrt
