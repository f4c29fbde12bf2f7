// Finite-element radiosity (docs/radiosity.md): the diffuse light of the scene solved once
// on patches, then shown through the camera pass after pass.
#pragma once
#include "math/path_sampler.h"
#include "integrators/integrator.h"
#include "integrators/radiosity/radiosity_solver.h"

namespace photon {

// Radiance along a camera ray under a radiosity solution: emission where seen, the
// Gouraud-interpolated radiosity of the first diffuse surface (L = rho I / pi, rho the
// reflectance at the hit), and specular surfaces followed by sampling their BSDF for up
// to maxDepth vertices.
Color radiosityRadiance(const Scene& scene, const RadiositySolution& solution, Ray ray, PathSampler& sampler,
                        int maxDepth);

std::unique_ptr<Integrator> makeRadiosityIntegrator(std::shared_ptr<const Scene> scene);

}  // namespace photon
