// How to render: the scene's "render" block. Integrators read the fields they use.
#pragma once
#include <cstdint>
#include <string>

namespace photon {

enum class IntegratorKind { Sppm, Path, PhotonMap };
enum class KernelKind { Uniform, Biweight, Cone };
// Where SPPM takes direct light at visible points from.
enum class DirectLighting { LightSampling, Photons };

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
    float initialRadius = 0;          // 0: "auto", from each pixel's footprint
    float alpha = 2.0f / 3.0f;        // fraction of new photons kept per pass (Hachisuka & Jensen 2009)
    int maxDepth = 8;                 // path vertices after the camera or light
    uint64_t seed = 1;
    KernelKind kernel = KernelKind::Uniform;
    float exposure = 0;               // stops, applied when tone mapping to PNG
    DirectLighting direct = DirectLighting::LightSampling;
    bool projectionMaps = true;       // emit photons only toward geometry (Jensen 2001, 5.1.3)
    PhotonMapSettings photonMap;
};

}  // namespace photon
