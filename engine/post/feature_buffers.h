// First-hit feature buffers, the guides of the cross (joint) bilateral denoiser
// (Eisemann & Durand 2004; Petschnigg et al. 2004): per pixel, the albedo and shading
// normal of the first surface a camera ray sees that is not a pure delta reflector or
// refractor. They depend on the scene alone, not on any integrator, so every integrator
// shares them and a render computes them once.
#pragma once
#include <photon/image.h>

namespace photon {

class Scene;

struct FeatureBuffers {
    // Per pixel, the mean over the jittered rays of
    //   albedo: the material's tint at the first non-delta hit, times the throughput of the
    //           delta bounces before it (a mirror of reflectance 0.9 shows 0.9 x what it
    //           reflects); zero where the ray escapes to the environment, is absorbed, or
    //           is still on delta bounces after render.max_depth vertices;
    //   normal: the world-space shading normal there, turned toward the arriving ray for
    //           two-sided materials; zero where albedo is zero for one of those reasons.
    // Normals are averaged unnormalised, so a pixel straddling an edge has a shorter,
    // in-between normal: exactly what the guide should see there.
    Image albedo;
    Image normal;
};

// `samplesPerPixel` jittered camera rays per pixel, followed through delta bounces as the
// SPPM camera pass does. Deterministic: each pixel's random numbers are keyed by the seed
// and the pixel index (StreamPurpose::Features), never by the thread.
FeatureBuffers renderFeatureBuffers(const Scene& scene, int samplesPerPixel);

}  // namespace photon
