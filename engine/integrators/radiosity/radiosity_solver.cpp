#include "integrators/radiosity/radiosity_solver.h"
#include <chrono>
#include "integrators/common/milliseconds_since.h"

namespace photon {

namespace {

Color gather(const std::vector<FormFactorEntry>& row, const std::vector<Color>& reflected) {
    Color sum(0.0f);
    for (const FormFactorEntry& e : row) sum += reflected[e.patch] * e.value;
    return sum;
}

float maxAbs(Color c) { return maxComponent(vmax(c, -c)); }

}  // namespace

std::optional<SolveResult> solveGaussSeidel(const std::vector<Patch>& patches, const FormFactors& F,
                                            const std::vector<Color>& direct, float tolerance, int maxIterations,
                                            const CancelToken& cancel) {
    SolveResult result;
    result.reflected.resize(patches.size());
    float maxEmitted = 0;
    for (size_t i = 0; i < patches.size(); ++i) {
        result.reflected[i] = patches[i].albedo * direct[i];
        maxEmitted = std::max(maxEmitted, maxComponent(patches[i].exitance));
    }
    for (int sweep = 0; sweep < maxIterations; ++sweep) {
        if (cancel.cancelled()) return std::nullopt;
        float maxChange = 0, maxB = maxEmitted;
        for (size_t i = 0; i < patches.size(); ++i) {
            Color r = patches[i].albedo * (direct[i] + gather(F.rows[i], result.reflected));
            maxChange = std::max(maxChange, maxAbs(r - result.reflected[i]));
            maxB = std::max(maxB, maxComponent(patches[i].exitance + r));
            result.reflected[i] = r;
        }
        result.iterations = sweep + 1;
        result.residual = maxB > 0 ? maxChange / maxB : 0;
        if (result.residual < tolerance) break;
    }
    return result;
}

std::unique_ptr<RadiositySolution> RadiositySolution::compute(const Scene& scene, const CancelToken& cancel) {
    auto start = std::chrono::steady_clock::now();
    const RenderSettings& s = scene.settings();
    const RadiositySettings& rs = s.radiosity;
    std::unique_ptr<RadiositySolution> sol(new RadiositySolution(PatchMesh(scene, rs)));
    const std::vector<Patch>& patches = sol->mesh_.patches();
    RadiosityLights lights(scene, sol->mesh_, rs.raysPerPatch, rs.directSamples);
    auto F = computeFormFactors(scene, sol->mesh_, lights, s.seed, cancel);
    if (!F) return nullptr;
    sol->formFactors_ = std::move(*F);
    auto H = directIrradiance(scene, sol->mesh_, lights, s.seed, cancel);
    if (!H) return nullptr;
    sol->direct_ = std::move(*H);
    for (size_t i = 0; i < patches.size(); ++i) sol->direct_[i] += sol->formFactors_.emitterIrradiance[i];
    auto solved = solveGaussSeidel(patches, sol->formFactors_, sol->direct_, rs.tolerance, rs.maxIterations, cancel);
    if (!solved) return nullptr;
    sol->iterations_ = solved->iterations;
    sol->residual_ = solved->residual;
    sol->irradiance_.resize(patches.size());
    for (size_t i = 0; i < patches.size(); ++i)
        sol->irradiance_[i] = sol->direct_[i] + gather(sol->formFactors_.rows[i], solved->reflected);
    sol->averageAtVertices();
    sol->milliseconds_ = millisecondsSince(start);
    return sol;
}

Color RadiositySolution::radiosity(size_t i) const {
    const Patch& p = mesh_.patches()[i];
    return p.exitance + p.albedo * irradiance_[i];
}

// Gouraud shading's vertex values: the area-weighted mean over the cells that share the
// vertex (Cohen & Wallace 1993, 10.1.1).
void RadiositySolution::averageAtVertices() {
    vertexIrradiance_.assign(2 * mesh_.vertexCount(), Color(0.0f));
    std::vector<float> weight(vertexIrradiance_.size(), 0.0f);
    const std::vector<Patch>& patches = mesh_.patches();
    for (size_t i = 0; i < patches.size(); ++i) {
        const PatchCell& cell = mesh_.cells()[patches[i].cell];
        for (int k = 0; k < cell.cornerCount; ++k) {
            size_t v = 2 * size_t(cell.corners[k]) + patches[i].back;
            vertexIrradiance_[v] += irradiance_[i] * patches[i].area;
            weight[v] += patches[i].area;
        }
    }
    for (size_t v = 0; v < weight.size(); ++v)
        if (weight[v] > 0) vertexIrradiance_[v] /= weight[v];
}

std::optional<Color> RadiositySolution::irradianceAt(const SurfaceHit& hit, Vec3 wo) const {
    std::optional<CellPoint> at = mesh_.locate(hit);
    if (!at) return std::nullopt;
    const PatchCell& cell = mesh_.cells()[at->cell];
    bool back = mesh_.patches()[mesh_.patchSeenFrom(*at, hit, wo)].back;
    Color sum(0.0f);
    for (int k = 0; k < cell.cornerCount; ++k) sum += vertexIrradiance_[2 * size_t(cell.corners[k]) + back] * at->weights[k];
    return sum;
}

}  // namespace photon
