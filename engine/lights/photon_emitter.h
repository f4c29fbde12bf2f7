// Where photons come from, for every photon integrator: a light picked in proportion to
// its power, then a ray from it, through a projection map where the light has one.
#pragma once
#include <optional>
#include <vector>
#include "../math/rng.h"
#include "../scene/ray.h"
#include "projection_map.h"

namespace photon {

class Scene;

struct EmittedPhoton {
    Ray ray;
    // Flux in units of the lights' mean total power (LightSampler::totalAveragePower), so
    // that without projection maps a photon's flux averages 1.
    Color beta;
};

// What a projection map marks: every shape, or only shapes whose material has a delta
// (specular) lobe. Caustic paths (L S+ D) start at such a shape, so a caustic map loses
// nothing by emitting toward them alone (Jensen 2001, sec. 9.2), and gains many photons.
enum class PhotonTargets { AllShapes, SpecularShapes };

class PhotonEmitter {
public:
    // Builds projection maps for the point, spot and directional lights if asked to.
    PhotonEmitter(const Scene& scene, bool projectionMaps, PhotonTargets targets = PhotonTargets::AllShapes);

    // Draws five numbers from rng in every case (light, two for position, two for
    // direction), so the streams that follow do not depend on the light picked.
    std::optional<EmittedPhoton> emit(Rng& rng) const;

    // The map of the sampler's light i, or null.
    const ProjectionMap* projectionMap(size_t light) const {
        return maps_[light] ? &*maps_[light] : nullptr;
    }

private:
    const Scene& scene_;
    std::vector<std::optional<ProjectionMap>> maps_;  // by the light sampler's index
    // 1 / (probability of the light * the lights' mean total power), by the same index.
    std::vector<float> fluxScale_;
};

}  // namespace photon
