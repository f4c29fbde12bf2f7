// The photon random walk shared by the photon integrators (SPPM and the two-pass photon
// map): emission through the PhotonEmitter, scattering by BSDF sampling, Russian roulette
// on the maximum channel. Photons are walked sixteen at a time in lanes: their rays are
// cast together in one Embree packet query (a sixth less time per ray than one by one,
// docs/sppm.md), and the bounces off Lambertian surfaces (most of a walk's bounces),
// perfect mirrors and smooth dielectrics are sampled eight lanes at a time with SIMD
// instructions; every other material scatters lane by lane through its BSDF.
#pragma once
#include <cstdint>
#include "integrators/common/photon_emitter.h"
#include "integrators/common/shading.h"

namespace photon {

// A photon arriving at a surface that is not purely specular, or where it scatters in a
// medium (PhotonPathSettings::arrivesInMedia: no normal, and its flux weighted by the
// flight's odds, so that the flux arriving per unit volume and solid angle has mean
// sigma_s L, free_flight.h).
struct PhotonArrival {
    Vec3 p;             // where it landed
    Vec3 ns;            // the shading normal there, turned toward wi on two-sided materials (0 in a medium)
    Vec3 wi;            // toward where the photon came from
    Color flux;         // in the emitter's units (photons average 1 without projection maps)
    int depth;          // 0: straight from the light
    bool onlySpecular;  // every bounce before this one was off a delta lobe
    uint32_t cell;      // the emission guide's cell the photon left from (EmittedPhoton::cell)
};

// What the integrator does with arriving photons (splat them, store them).
class PhotonArrivalSink {
public:
    virtual void arrive(const PhotonArrival& a) = 0;

protected:
    ~PhotonArrivalSink() = default;
};

struct PhotonPathSettings {
    uint64_t seed = 0;
    uint64_t stream = 0;  // with the seed and the photon's index, keys its random numbers
    int maxDepth = 8;     // surfaces a photon reaches at most
    // Follow only delta bounces (a caustic map): a path ends at its first non-delta sample.
    bool specularOnly = false;
    // Arrivals at smaller depths are not handed to the sink (1: no photons straight from
    // the lights, where direct light is found another way).
    int firstArrivalDepth = 0;
    // Photons of lights no light sample is taken toward (Light::sampledDirectly: a medium
    // that emits) arrive from their first hit whatever firstArrivalDepth: they bring that
    // light's direct part, which nothing else does.
    bool unsampledLightsArriveFirst = false;
    // Arrivals also where photons scatter in media (a volumetric photon map's photons); else
    // only on surfaces.
    bool arrivesInMedia = false;
};

struct PhotonPathCounters {
    int64_t rays = 0;              // rays cast, escaping ones included
    int64_t segments = 0;          // rays that reached a surface
    int64_t missedAtEmission = 0;  // photons whose first ray left the scene
};

// Traces photons [begin, end). The random numbers of photon i come from (seed, stream, i)
// alone, so paths do not depend on threads (nor on the lane a photon is walked in).
void tracePhotonPaths(const Scene& scene, const PhotonEmitter& emitter, const PhotonPathSettings& settings,
                      int64_t begin, int64_t end, PhotonArrivalSink& sink, PhotonPathCounters& counters);

}  // namespace photon
