// Direct light at a surface point by one light sample and a shadow ray (next-event
// estimation), shared by the SPPM camera pass and the path tracer.
#pragma once
#include "math/rng.h"
#include "integrators/common/shading.h"

namespace photon {

// Reflected radiance toward wo (world space) from one light picked in proportion to power,
// through the material's `lobes` only.
Color sampleDirectLight(const Scene& scene, const ShadingPoint& sp, Vec3 wo, Rng& rng, unsigned lobes = kAllLobes);

}  // namespace photon
