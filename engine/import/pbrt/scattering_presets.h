// Measured scattering coefficients that pbrt-v4 scenes name: a subsurface material's "name"
// and a homogeneous medium's "preset". The materials Jensen, Marschner, Levoy and Hanrahan
// measured ("A Practical Model for Subsurface Light Transport", SIGGRAPH 2001, table 2):
// reduced scattering sigma_s' and absorption sigma_a in mm^-1 for red, green and blue,
// which pbrt-v4 takes as sigma_s and sigma_a (with g = 0) before its "scale".
//
// A subsurface material given a diffuse reflectance and a mean free path instead is turned
// into coefficients by inverting the classical diffusion dipole's total diffuse reflectance
// (Jensen et al. 2001, eq. 2 with the Fresnel fit of Egan and Hilgeman for F_dr), where
// pbrt-v4 inverts a table of photon beam diffusion (Habel et al. 2013): the two differ by a
// few percent in the albedo found.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <photon/vec.h>

namespace photon::pbrt {

struct ScatteringCoefficients {
    Color absorption, scattering;  // mm^-1
};

// The named measurement, or nullopt for a name not in the table.
std::optional<ScatteringCoefficients> scatteringPreset(std::string_view name);
// The names the table holds, for messages: "Apple, Chicken1, ...".
std::string scatteringPresetNames();

// The dipole's total diffuse reflectance of a semi-infinite medium of single-scattering
// albedo `albedo` (g = 0) under a boundary of relative index `eta`.
double dipoleDiffuseReflectance(double albedo, double eta);
// Its inverse: the albedo in [0, 1] whose reflectance is `reflectance` (clamped to what
// albedos 0 and 1 give).
double albedoOfDiffuseReflectance(double reflectance, double eta);

}  // namespace photon::pbrt
