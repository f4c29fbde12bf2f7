// The integrator a scene's render block names: the one place that knows every family
// (above them all, beside the face's Renderer that uses it).
#pragma once
#include <memory>
#include "integrators/integrator.h"

namespace photon {

std::unique_ptr<Integrator> makeIntegrator(std::shared_ptr<const Scene> scene);

}  // namespace photon
