// What couples the patches: Monte Carlo form factors with Embree visibility, and the
// first-shot direct irradiance from every light by shadow rays. Both are deterministic:
// each patch draws from its own random stream, keyed by the patch index.
#pragma once
#include <vector>
#include "integrator.h"
#include "radiosity_patches.h"

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
};

// F_ij by cosine-distributed rays from uniform points on patch i (Cohen & Wallace 1993,
// 4.9; the fraction of rays that land on j estimates F_ij, visibility included). Rays
// that hit a surface without patches (mirror, glass, glossy metal) are absorbed.
// Returns nullopt if cancelled.
std::optional<FormFactors> computeFormFactors(const Scene& scene, const PatchMesh& mesh, int raysPerPatch,
                                              uint64_t seed, const CancelToken& cancel);

// Irradiance H_i (W/m^2) that reaches each patch side straight from the lights (emissive
// shapes, point, spot, directional and environment lights): `samples` stratified points
// on the patch, each with a light picked in proportion to power and a shadow ray.
std::optional<std::vector<Color>> directIrradiance(const Scene& scene, const PatchMesh& mesh, int samples,
                                                   uint64_t seed, const CancelToken& cancel);

}  // namespace photon
