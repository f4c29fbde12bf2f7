// Direct light at a surface point by one light sample and a shadow ray (next-event
// estimation), shared by the SPPM camera pass and the path tracer.
#pragma once
#include "math/path_sampler.h"
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
// through the material's `lobes` only. Its draws: the light (1D), the point on it (2D), and
// for a material that transmits, the side (1D). `medium`: the one the path arrived in at
// sp; the shadow ray starts in the medium on the light's side of the surface and takes on
// the absorption of each medium it crosses (Scene::shadowTransmittance). `fitted`: whether
// the light fits its sample to this point (ReceiverSide::fitted; the BounceSampling of the
// path's continuation must say the same).
Color sampleDirectLight(const Scene& scene, const ShadingPoint& sp, Vec3 wo, PathSampler& sampler,
                        unsigned lobes = kAllLobes, BsdfContinuation next = {}, int32_t medium = -1,
                        bool fitted = true);
// In-scattered radiance toward wo at a point p where a path scatters in `medium`, from one
// light picked by Scene::directLights, through the medium's phase function, weighted
// against the phase-function sample the path goes on with (scatterInMedium, shading.h).
// Lights sample directions above a normal, and a point in a medium has none: the sample is
// taken for the half of the sphere on wo's side or the other, each with probability 1/2
// (unbiased, as for a surface that transmits). Its draws: the light (1D), the side (1D),
// the point on the light (2D). `continues` false: the path ends here (an SPPM visible point
// in the medium), and the light sample counts in full against the phase function. `along`:
// the segment p's flight scattered on, where light may have been sampled along the ray too
// (weightAgainstLightAlongRay).
Color sampleDirectLightInMedium(const Scene& scene, Vec3 p, Vec3 wo, int32_t medium, PathSampler& sampler,
                                bool continues = true, const FlightSegment* along = nullptr);
// The same with every number from `rng`.
inline Color sampleDirectLight(const Scene& scene, const ShadingPoint& sp, Vec3 wo, Rng& rng,
                               unsigned lobes = kAllLobes, BsdfContinuation next = {}, int32_t medium = -1) {
    PathSampler sampler(rng);
    return sampleDirectLight(scene, sp, wo, sampler, lobes, next, medium);
}

}  // namespace photon
