// How to render: the scene's "render" block. Integrators read the fields they use.
#pragma once
#include <cstdint>
#include <string>

namespace photon {

enum class IntegratorKind { Sppm, Path, Radiosity };
enum class KernelKind { Uniform, Biweight };
// Where SPPM takes direct light at visible points from.
enum class DirectLighting { LightSampling, Photons };

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

struct RenderSettings {
    IntegratorKind integrator = IntegratorKind::Sppm;
    int passes = 64;                  // SPPM passes, or samples per pixel for the path tracer
    int64_t photonsPerPass = 200000;
    double timeLimitSeconds = 0;      // 0: no limit; otherwise stop after the pass that crosses it
    float initialRadius = 0;          // 0: "auto", from each pixel's footprint
    float alpha = 2.0f / 3.0f;        // fraction of new photons kept per pass (Hachisuka & Jensen 2009)
    int maxDepth = 8;                 // path vertices after the camera or light
    uint64_t seed = 1;
    KernelKind kernel = KernelKind::Uniform;
    float exposure = 0;               // stops, applied when tone mapping to PNG
    DirectLighting direct = DirectLighting::LightSampling;
    RadiositySettings radiosity;
    DenoiseSettings denoise;
};

}  // namespace photon
