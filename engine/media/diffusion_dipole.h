// A scattering medium described by what it looks like instead of by its coefficients: the
// diffuse reflectance of a deep slab of it and the mean free path of light in it, as artists
// give skin, wax or marble and as pbrt-v4's "subsurface" material takes them. The albedo is
// found by inverting the classical diffusion dipole's total diffuse reflectance (Jensen,
// Marschner, Levoy and Hanrahan 2001, "A Practical Model for Subsurface Light Transport",
// eq. 2, with the Fresnel fit of Egan and Hilgeman for F_dr), where pbrt-v4 inverts a table
// of photon beam diffusion (Habel et al. 2013): the two differ by a few percent in the albedo.
#pragma once
#include <photon/vec.h>

namespace photon {

// The dipole's total diffuse reflectance of a semi-infinite medium of single-scattering
// albedo `albedo` (g = 0) under a boundary of relative index `eta`.
double dipoleDiffuseReflectance(double albedo, double eta);
// Its inverse: the albedo in [0, 1] whose reflectance is `reflectance` (clamped to what
// albedos 0 and 1 give).
double albedoOfDiffuseReflectance(double reflectance, double eta);

struct ScatteringCoefficients {
    Color absorption, scattering;  // per unit length
};
// sigma_t = 1 / meanFreePath per channel, split by the albedo whose dipole reflectance under
// a boundary of index `eta` is `reflectance` (each channel clamped to [0, 1]);
// meanFreePath > 0.
ScatteringCoefficients coefficientsOfReflectance(Color reflectance, Color meanFreePath, double eta);

}  // namespace photon
