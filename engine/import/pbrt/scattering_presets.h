// Measured scattering coefficients that pbrt-v4 scenes name: a subsurface material's "name"
// and a homogeneous medium's "preset". The materials Jensen, Marschner, Levoy and Hanrahan
// measured ("A Practical Model for Subsurface Light Transport", SIGGRAPH 2001, table 2):
// reduced scattering sigma_s' and absorption sigma_a in mm^-1 for red, green and blue,
// which pbrt-v4 takes as sigma_s and sigma_a (with g = 0) before its "scale".
// (A subsurface material given a diffuse reflectance and a mean free path instead becomes a
// medium of that reflectance: media/diffusion_dipole.h.)
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include "media/diffusion_dipole.h"

namespace photon::pbrt {

using photon::ScatteringCoefficients;  // in mm^-1

// The named measurement, or nullopt for a name not in the table.
std::optional<ScatteringCoefficients> scatteringPreset(std::string_view name);
// The names the table holds, for messages: "Apple, Chicken1, ...".
std::string scatteringPresetNames();

}  // namespace photon::pbrt
