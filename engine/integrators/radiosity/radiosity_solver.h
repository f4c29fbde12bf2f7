// The radiosity system and its solution. With B = E + R (emitted plus reflected
// radiosity, W/m^2) the classic equation B_i = E_i + rho_i sum_j F_ij B_j (Goral et al.
// 1984; Cohen & Wallace 1993, eq. 3.10) is solved for R, with the light that arrives
// straight from emitters and other lights taken by shadow rays (first shot) instead of
// through F:
//     R_i = rho_i (H_i + sum_j F_ij R_j),   I_i = H_i + sum_j F_ij R_j,
// H_i the direct irradiance, I_i all irradiance reaching patch side i. The radiance
// leaving a Lambertian patch is L = B / pi = Le + rho I / pi.
#pragma once
#include <memory>
#include <vector>
#include "integrators/radiosity/radiosity_patches.h"
#include "integrators/radiosity/radiosity_transport.h"

namespace photon {

struct SolveResult {
    std::vector<Color> reflected;  // R_i, W/m^2
    int iterations = 0;
    float residual = 0;  // last sweep's max |change of R| over max B (all channels)
};

// Gauss-Seidel sweeps in patch order (deterministic) until the residual is below
// `tolerance` or `maxIterations` sweeps are done; nullopt if cancelled between sweeps.
std::optional<SolveResult> solveGaussSeidel(const std::vector<Patch>& patches, const FormFactors& F,
                                            const std::vector<Color>& direct, float tolerance, int maxIterations,
                                            const CancelToken& cancel);

// Everything the radiosity integrator computes once per scene: patches, form factors,
// direct light, the solution and its values at the patches' shared vertices.
class RadiositySolution {
public:
    // Nullopt if cancelled; std::runtime_error if the scene needs too many patches.
    static std::unique_ptr<RadiositySolution> compute(const Scene& scene, const CancelToken& cancel);

    const PatchMesh& mesh() const { return mesh_; }
    const FormFactors& formFactors() const { return formFactors_; }
    const std::vector<Color>& direct() const { return direct_; }          // H_i
    const std::vector<Color>& irradiance() const { return irradiance_; }  // I_i
    Color radiosity(size_t i) const;                                       // B_i = E_i + rho_i I_i
    int iterations() const { return iterations_; }
    float residual() const { return residual_; }
    double milliseconds() const { return milliseconds_; }

    // Irradiance at a hit on a patched surface, interpolated (Gouraud) from the
    // area-weighted averages at the corners of its cell, on the side `wo` is on.
    std::optional<Color> irradianceAt(const SurfaceHit& hit, Vec3 wo) const;

private:
    explicit RadiositySolution(PatchMesh mesh) : mesh_(std::move(mesh)) {}
    void averageAtVertices();

    PatchMesh mesh_;
    FormFactors formFactors_;
    std::vector<Color> direct_, irradiance_;
    std::vector<Color> vertexIrradiance_;  // two per vertex: front side, back side
    int iterations_ = 0;
    float residual_ = 0;
    double milliseconds_ = 0;
};

}  // namespace photon
