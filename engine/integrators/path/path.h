// The reference path tracer.
#pragma once
#include "math/path_sampler.h"
#include "scene/scene.h"
#include "integrators/integrator.h"

namespace photon {

// Radiance along a camera ray: emission after delta bounces, direct light by shadow rays
// at every other vertex, Russian roulette after three bounces.
Color traceRadiance(const Scene& scene, Ray ray, PathSampler& sampler, int maxDepth);
std::unique_ptr<Integrator> makePathIntegrator(std::shared_ptr<const Scene> scene);

}  // namespace photon
