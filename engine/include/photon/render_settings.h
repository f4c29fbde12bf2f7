// How to render: the scene's "render" block. Integrators read the fields they use.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <string>

namespace photon {

enum class IntegratorKind { Sppm, Path, Radiosity, PhotonMap };
// Their names in scenes (render.integrator), on the command line and in the API, in the
// enum's order.
inline constexpr std::array<std::string_view, 4> kIntegratorNames{"sppm", "path", "radiosity", "photonmap"};
inline std::string_view integratorName(IntegratorKind kind) { return kIntegratorNames[static_cast<size_t>(kind)]; }
inline std::optional<IntegratorKind> integratorNamed(std::string_view name) {
    for (size_t i = 0; i < kIntegratorNames.size(); ++i)
        if (kIntegratorNames[i] == name) return IntegratorKind(i);
    return std::nullopt;
}
enum class KernelKind { Uniform, Biweight, Cone };
// Where SPPM takes direct light at visible points from.
enum class DirectLighting { LightSampling, Photons };
// How SPPM shrinks its gather radii. PerPixel: Hachisuka & Jensen 2009's per-pixel
// statistics, each pixel's radius following its own photon counts, so a pass depends on
// every pass before it. Global: Knaus & Zwicker 2011's schedule, the same for every pixel,
// r_i^2 = r_1^2 prod_{k<i} (k + alpha) / (k + 1), r_1 from the pass's own visible point; each
// pass is then an independent estimate, and passes rendered anywhere, in any order, add up
// (docs/sppm.md, "Independent passes").
enum class RadiusSchedule { PerPixel, Global };
// How a shadow ray picks its light (render.light_sampler; engine/lights/direct_light_sampler.h):
// among finite lights by a bound on what each could bring to the point, or by power alone.
enum class LightSamplerKind { Spatial, Power };
// How SPPM's camera path chooses between a material's diffuse base and its other lobes (a
// coat's or plastic's highlight) at the path's first such choice (render.lobe_choice;
// docs/sppm.md, "Learned lobe choice"): by the probability each pixel's earlier passes found
// best, or by the material's albedos alone.
enum class LobeChoice { Learned, Material };
// Where a camera path's random numbers come from (render.sampler; engine/math/path_sampler.h):
// Owen-scrambled Sobol sequences over each pixel's passes (or samples), or independent
// numbers.
enum class SamplerKind { Sobol, Independent };

// SPPM in media that scatter (RenderSettings::volumePhotons): whether photons are also
// gathered where they scatter in a medium. Auto: where the scene has a surface with a delta
// lobe (a mirror, smooth glass) to send light into the medium along paths no light sample
// finds, a volumetric caustic.
enum class VolumePhotons { Auto, Always, Never };

// Finite-element radiosity (docs/radiosity.md): how surfaces are cut into patches and how
// the form factors and the linear system are computed.
struct RadiositySettings {
    float patchSize = 0;          // target patch edge, scene units; 0: "auto", from the scene's size
    int64_t maxPatches = 50000;   // patch sides (unknowns) at most; the patch size grows to fit
    int raysPerPatch = 1024;      // form-factor rays cast from each patch side
    int directSamples = 64;       // shadow rays per patch side for the first-shot direct light
    float tolerance = 1e-4f;      // solver stops when max |change| / max radiosity is below it
    int maxIterations = 1000;     // Gauss-Seidel sweeps at most
};

// The optional post filter (render.denoise; docs/denoise.md): a bilateral filter of the
// snapshot, guided by first-hit albedo and normal buffers. It never changes the render's
// state, so it is not part of a checkpoint's fingerprint.
struct DenoiseSettings {
    bool enabled = false;
    float sigmaSpatial = 1.5f;   // pixels
    float sigmaRange = 1.0f;     // on the difference of log colours
    bool guide = true;           // weigh by the albedo and normal buffers too
    float sigmaAlbedo = 0.1f;    // on the albedo difference
    float sigmaNormal = 0.2f;    // on the (averaged) normal difference
    int featureSamples = 4;      // jittered rays per pixel for the guide buffers
};

// Two-pass photon mapping (Jensen 1996): how many photons build each map and how each
// radiance estimate looks them up.
struct PhotonMapSettings {
    int64_t globalPhotons = 200000;   // photons emitted to build the global map
    int64_t causticPhotons = 200000;  // photons emitted to build the caustic map
    int globalNearest = 100;          // k: photons per global-map estimate
    int causticNearest = 50;          // k: photons per caustic-map estimate
    float globalMaxRadius = 0;        // 0: "auto", a tenth of the scene's bounding-sphere radius
    float causticMaxRadius = 0;       // 0: "auto", a fortieth of the scene's bounding-sphere radius
    int gatherRays = 64;              // final-gather rays per camera hit; 0: global map read directly
    bool precomputedIrradiance = true;  // gather rays read irradiance precomputed at photons (Christensen 1999)
};

struct RenderSettings {
    IntegratorKind integrator = IntegratorKind::Sppm;
    int passes = 64;                  // SPPM passes, or samples per pixel for the path tracer
    int64_t photonsPerPass = 200000;
    double timeLimitSeconds = 0;      // 0: no limit; otherwise stop after the pass that crosses it
    // 0: none; otherwise stop after the pass whose estimated relative error
    // (RenderProgress::relativeError) is at or below it, e.g. 0.02.
    double targetError = 0;
    float initialRadius = 0;          // 0: "auto", from each pixel's footprint
    // With "auto": photons one pass is to put in a disc (docs/sppm.md, "The auto radius").
    float autoRadiusPhotons = 8;
    float alpha = 2.0f / 3.0f;        // fraction of new photons kept per pass (Hachisuka & Jensen 2009)
    int maxDepth = 8;                 // path vertices after the camera or light
    uint64_t seed = 1;
    KernelKind kernel = KernelKind::Uniform;
    float exposure = 0;               // stops, applied when tone mapping to PNG
    DirectLighting direct = DirectLighting::LightSampling;
    bool projectionMaps = true;       // emit photons only toward geometry (Jensen 2001, 5.1.3)
    RadiusSchedule radiusSchedule = RadiusSchedule::PerPixel;
    // SPPM only: lightweight photon mapping (docs/sppm.md): camera paths are traced whole
    // and photons bring only caustics (light after delta bounces) to their first diffuse vertex.
    bool lightweight = false;
    // SPPM only, with the per-pixel schedule: photons leave the lights where earlier
    // passes' photons reached visible points (docs/sppm.md, "Photon guiding").
    bool photonGuiding = false;
    // SPPM with the per-pixel schedule: photons_per_pass is where the render starts, and the
    // photons a pass traces follow the split of the error between camera paths and photons,
    // and their costs (docs/sppm.md, "Photons per pass"). The other methods, and the global
    // schedule (whose passes are rendered apart), trace photons_per_pass in every pass.
    bool adaptivePhotons = true;
    // SPPM: a pass's camera paths and photons go in this many bands of rows, one band's
    // visible points and grid in memory at a time, each band tracing the pass's photons
    // again; the image is the same for any count. 0: "auto", one band up to 4 Mpx, else
    // bands of at most 1 Mpx (docs/sppm.md, "Memory").
    int bands = 0;
    LightSamplerKind lightSampler = LightSamplerKind::Spatial;
    LobeChoice lobeChoice = LobeChoice::Learned;
    SamplerKind sampler = SamplerKind::Sobol;
    // SPPM with the per-pixel schedule: each pixel traces as many camera paths a pass as its
    // camera-side variance and the pass's costs make worth it, the first storing the visible
    // point (docs/sppm.md, "Camera paths per pass").
    bool adaptiveCameraPaths = true;
    // SPPM with the per-pixel schedule: each pixel's radius shrinks as far as the bias its
    // photons' spread shows asks for, not by alpha's schedule alone (docs/sppm.md, "Radii
    // that follow the light").
    bool adaptiveRadius = true;
    // SPPM: where a pass's photons show that an edge cuts a visible point's disc, short rays
    // measure the share of the disc photons can land on, and the pass's estimate is divided
    // by it instead of counting area past the edge (docs/sppm.md, "Discs cut by edges").
    bool discCoverage = true;
    // SPPM in media that scatter: a camera path's visible point goes where it first scatters
    // in a medium, and photons are gathered there in a ball (a volumetric photon map's
    // estimate) as well as on surfaces (docs/sppm.md, "Volume photons"). Never: visible
    // points on surfaces only, the path going on through the medium.
    VolumePhotons volumePhotons = VolumePhotons::Auto;
    // The path tracer and SPPM's camera paths in media that scatter: each ray's segment
    // through such a medium also samples the light of a point or spot light along it by
    // equiangular distances (Kulla & Fajardo 2012), weighed against the light sample where
    // the ray's free flight scatters (docs/path.md, "Point lights in media").
    bool equiangular = true;
    PhotonMapSettings photonMap;
    RadiositySettings radiosity;
    DenoiseSettings denoise;
};

// Whether a render's photons per pass follow its error (RenderSettings::adaptivePhotons).
inline bool adaptsPhotonsPerPass(const RenderSettings& s) {
    return s.adaptivePhotons && s.integrator == IntegratorKind::Sppm && s.radiusSchedule == RadiusSchedule::PerPixel;
}

// Hands `visit` every setting that changes what a render's state becomes, in a fixed
// order: the one list a fingerprint of the settings (a checkpoint's key) is made from, kept
// beside the structs so that a new setting is added to it where it is declared. Left out:
// passes, the time limit and the target error (how far a render goes, not what it computes), and exposure and
// denoise (applied to snapshots, never to the state).
template <class Visit>
void visitStateSettings(const RenderSettings& s, Visit&& visit) {
    visit(s.integrator), visit(s.photonsPerPass), visit(s.initialRadius), visit(s.autoRadiusPhotons);
    visit(s.alpha), visit(s.maxDepth), visit(s.seed), visit(s.kernel), visit(s.direct), visit(s.projectionMaps);
    const PhotonMapSettings& p = s.photonMap;
    visit(p.globalPhotons), visit(p.causticPhotons), visit(p.globalNearest), visit(p.causticNearest);
    visit(p.globalMaxRadius), visit(p.causticMaxRadius), visit(p.gatherRays), visit(p.precomputedIrradiance);
    const RadiositySettings& r = s.radiosity;
    visit(r.patchSize), visit(r.maxPatches), visit(r.raysPerPatch), visit(r.directSamples), visit(r.tolerance);
    visit(r.maxIterations);
    // Visited only when not the default, so that checkpoints written before it existed keep
    // their key.
    if (s.radiusSchedule != RadiusSchedule::PerPixel) visit(s.radiusSchedule);
    if (s.lightweight) visit(s.lightweight);
    if (s.photonGuiding) visit(s.photonGuiding);
    // Visited where it acts, as when it was off by default: a checkpoint written with fixed
    // photon counts keeps its key, and SPPM goes on from it with fixed counts.
    if (adaptsPhotonsPerPass(s)) visit(true);
    // Visited only when not the default: a checkpoint written before the spatial light
    // sampler existed (by power) goes on with it, both being unbiased.
    if (s.lightSampler != LightSamplerKind::Spatial) visit(s.lightSampler);
    // Likewise: a checkpoint written before learned lobe choices existed goes on learning
    // from its resume (both choices are unbiased).
    if (s.lobeChoice != LobeChoice::Learned) visit(s.lobeChoice);
    // Likewise: a checkpoint written before camera paths were counted per pixel goes on
    // with them (one path a pixel a pass so far; AdaptiveCameraPaths::restore).
    if (!s.adaptiveCameraPaths) visit(s.adaptiveCameraPaths);
    // Likewise: a checkpoint written before the Sobol sampler existed goes on with it (both
    // samplers' passes are unbiased, and its odd and even passes stay independent).
    if (s.sampler != SamplerKind::Sobol) visit(s.sampler);
    // Likewise: a checkpoint written before volume photons existed goes on with "auto".
    if (s.volumePhotons != VolumePhotons::Auto) visit(s.volumePhotons);
    // Likewise: a checkpoint written before radii followed the light goes on with them, its
    // moments learnt anew (AdaptiveRadius::restore).
    if (!s.adaptiveRadius) visit(s.adaptiveRadius);
    // Likewise: a checkpoint written before discs' coverage was measured goes on with it.
    if (!s.discCoverage) visit(s.discCoverage);
    // Likewise: a checkpoint written before equiangular samples existed goes on with them.
    if (!s.equiangular) visit(s.equiangular);
}

// Whether SPPM's camera paths learn their lobe choice per pixel (RenderSettings::lobeChoice):
// with the per-pixel schedule only, whose passes already depend on the passes before them.
inline bool learnsLobeChoice(const RenderSettings& s) {
    return s.lobeChoice == LobeChoice::Learned && s.integrator == IntegratorKind::Sppm &&
           s.radiusSchedule == RadiusSchedule::PerPixel && !s.lightweight;
}

// Whether SPPM's pixels trace as many camera paths a pass as pays (adaptiveCameraPaths):
// with the per-pixel schedule only, as the counts come from earlier passes.
inline bool adaptsCameraPaths(const RenderSettings& s) {
    return s.adaptiveCameraPaths && s.integrator == IntegratorKind::Sppm &&
           s.radiusSchedule == RadiusSchedule::PerPixel && !s.lightweight;
}

// Whether SPPM measures the share of each disc photons can land on (discCoverage).
inline bool coversDiscs(const RenderSettings& s) { return s.discCoverage && s.integrator == IntegratorKind::Sppm; }

// Whether SPPM's radii follow each pixel's photons (adaptiveRadius): with the per-pixel
// schedule only, whose radii are per pixel.
inline bool adaptsRadius(const RenderSettings& s) {
    return s.adaptiveRadius && s.integrator == IntegratorKind::Sppm && s.radiusSchedule == RadiusSchedule::PerPixel;
}

}  // namespace photon
