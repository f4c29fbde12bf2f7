#include "integrators/radiosity/radiosity_lights.h"
#include <algorithm>
#include "lights/light_factories.h"

namespace photon {

RadiosityLights::RadiosityLights(const Scene& scene, const PatchMesh& mesh, int raysPerPatch, int directSamples)
    : mesh_(mesh), rays_(raysPerPatch), samples_(directSamples), probability_(mesh.patches().size(), 0.0f) {
    double sum = 0;
    const std::vector<Patch>& patches = mesh.patches();
    for (uint32_t i = 0; i < patches.size(); ++i) {
        double power = double(average(patches[i].exitance)) * patches[i].area;
        if (!(power > 0)) continue;
        emitters_.push_back(i);
        sum += power;
        cdf_.push_back(static_cast<float>(sum));
    }
    for (size_t k = 0; k < emitters_.size(); ++k) {
        const Patch& p = patches[emitters_[k]];
        probability_[emitters_[k]] = static_cast<float>(double(average(p.exitance)) * p.area / sum);
        cdf_[k] = static_cast<float>(cdf_[k] / sum);
    }
    if (!cdf_.empty()) cdf_.back() = 1.0f;
    // The scene's bounding sphere, as Scene gives it to its own infinite lights.
    Vec3 c = (scene.boundsMin() + scene.boundsMax()) * 0.5f;
    SceneSphere sphere{c, std::max(length(scene.boundsMax() - c), 1e-3f)};
    for (const LightDescription& d : scene.description().lights) {
        switch (d.kind) {
            case LightDescription::Kind::Point: others_.push_back(makePointLight(d)); break;
            case LightDescription::Kind::Spot: others_.push_back(makeSpotLight(d)); break;
            case LightDescription::Kind::Projection: others_.push_back(makeProjectionLight(d)); break;
            case LightDescription::Kind::Directional: others_.push_back(makeDirectionalLight(d, sphere)); break;
            case LightDescription::Kind::Environment: others_.push_back(makeEnvironmentLight(d, sphere)); break;
        }
    }
}

std::optional<RadiosityLights::EmitterPick> RadiosityLights::pickEmitter(float u) const {
    if (emitters_.empty()) return std::nullopt;
    size_t k = std::min(static_cast<size_t>(std::upper_bound(cdf_.begin(), cdf_.end(), u) - cdf_.begin()),
                        emitters_.size() - 1);
    return EmitterPick{emitters_[k], probability_[emitters_[k]]};
}

float RadiosityLights::misScale(uint32_t emitter, float cosReceiver, float distance, float cosEmitter) const {
    // Light sampling: pick probability times the area density 1/A in solid angle, d^2/(A cos).
    float pLight = probability_[emitter] * distance * distance / (mesh_.patches()[emitter].area * cosEmitter);
    float pCosine = cosReceiver * kInvPi;
    return 1.0f / (static_cast<float>(samples_) * pLight + static_cast<float>(rays_) * pCosine);
}

}  // namespace photon
