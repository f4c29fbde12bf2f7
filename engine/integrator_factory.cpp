#include "integrator_factory.h"
#include "integrators/path/path.h"
#include "integrators/photon_mapping/photon_mapping.h"
#include "integrators/radiosity/radiosity.h"
#include "integrators/sppm/sppm.h"

namespace photon {

std::unique_ptr<Integrator> makeIntegrator(std::shared_ptr<const Scene> scene) {
    switch (scene->settings().integrator) {
        case IntegratorKind::Path: return makePathIntegrator(std::move(scene));
        case IntegratorKind::Radiosity: return makeRadiosityIntegrator(std::move(scene));
        case IntegratorKind::PhotonMap: return std::make_unique<PhotonMapIntegrator>(std::move(scene));
        case IntegratorKind::Sppm: break;
    }
    return std::make_unique<SppmIntegrator>(std::move(scene));
}

}  // namespace photon
