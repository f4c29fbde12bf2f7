// What couples the patches: Monte Carlo form factors with Embree visibility, and the
// first-shot direct irradiance from every light by shadow rays. Both are deterministic:
// each patch draws from its own random stream, keyed by the patch index.
#pragma once
#include <vector>
#include "integrators/integrator.h"
#include "integrators/radiosity/radiosity_lights.h"

namespace photon {

// Row i of the form-factor matrix, sparse: only the patches its rays reached.
struct FormFactorEntry {
    uint32_t patch;
    float value;
};
struct FormFactors {
    std::vector<std::vector<FormFactorEntry>> rows;
    int64_t rays = 0;     // cast in all
    int64_t escaped = 0;  // left the scene
    // Irradiance from emitters found by these rays, MIS-weighted (radiosity_lights.h), W/m^2.
    std::vector<Color> emitterIrradiance;
};

// F_ij by cosine-distributed rays from uniform points on patch i (Cohen & Wallace 1993,
// 4.9; the fraction of rays that land on j estimates F_ij, visibility included). Rays
// that hit a surface without patches (mirror, glass, glossy metal) are absorbed.
// lights.raysPerPatch() rays per patch side. Returns nullopt if cancelled.
std::optional<FormFactors> computeFormFactors(const Scene& scene, const PatchMesh& mesh, const RadiosityLights& lights,
                                              uint64_t seed, const CancelToken& cancel);

// Irradiance (W/m^2) that reaches each patch side straight from the lights by shadow rays
// from lights.directSamples() stratified points on it: to a point on an emitter picked by
// power (MIS-weighted, the other half of FormFactors::emitterIrradiance), and to each
// other light.
std::optional<std::vector<Color>> directIrradiance(const Scene& scene, const PatchMesh& mesh,
                                                   const RadiosityLights& lights, uint64_t seed,
                                                   const CancelToken& cancel);

}  // namespace photon
