// Direct light at a surface point by one light sample and a shadow ray (next-event
// estimation), shared by the SPPM camera pass and the path tracer.
#pragma once
#include "../math/rng.h"
#include "shading.h"

namespace photon {

// Reflected radiance toward wo (world space) from one light picked in proportion to power.
Color sampleDirectLight(const Scene& scene, const ShadingPoint& sp, Vec3 wo, Rng& rng);

}  // namespace photon
