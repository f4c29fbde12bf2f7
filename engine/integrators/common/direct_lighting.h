// Direct light at a surface point by one light sample and a shadow ray (next-event
// estimation), shared by the SPPM camera pass and the path tracer.
#pragma once
#include "math/rng.h"
#include "integrators/common/shading.h"

namespace photon {

// The BSDF sampling a camera path goes on with after the light sample at a vertex: with
// `probability` it samples its next direction from `lobes`. Light that both can find (an
// area light's or the environment's, through those lobes) is shared between them by the
// power heuristic (Veach 1997, ch. 9); the path then counts the light its next ray reaches
// with the matching weight (traceCameraRay with a BounceSampling, shading.h). No
// continuation (lobes 0): the light sample counts in full, as for delta lights always.
struct BsdfContinuation {
    unsigned lobes = 0;
    float probability = 0;
};

// Reflected radiance toward wo (world space) from one light picked by Scene::directLights,
// through the material's `lobes` only.
Color sampleDirectLight(const Scene& scene, const ShadingPoint& sp, Vec3 wo, Rng& rng, unsigned lobes = kAllLobes,
                        BsdfContinuation next = {});

}  // namespace photon
