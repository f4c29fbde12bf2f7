// The lights as the radiosity setup sees them. Emissive surfaces are patches: their light
// reaches a patch both through form-factor rays that happen to hit them and through
// shadow rays to points sampled on them, and the two are combined by multiple importance
// sampling (Veach 1997, ch. 9, balance heuristic), so that neither a small light (few rays
// find it) nor a large emitter next to the receiver (1/d^2 samples) leaves noisy patches.
// Point, spot, directional and environment lights are sampled by shadow rays alone.
#pragma once
#include <memory>
#include <vector>
#include "lights/light.h"
#include "integrators/radiosity/radiosity_patches.h"

namespace photon {

class RadiosityLights {
public:
    RadiosityLights(const Scene& scene, const PatchMesh& mesh, int raysPerPatch, int directSamples);

    struct EmitterPick {
        uint32_t patch = 0;
        float probability = 0;  // of picking this patch side
    };
    // An emitting patch side picked in proportion to its power; nullopt if there is none.
    std::optional<EmitterPick> pickEmitter(float u) const;
    // Balance-heuristic weight / density for light from emitter patch j arriving at a
    // receiver with cosine cosReceiver, from a point at distance d with cosine cosEmitter:
    // 1 / (K p_light + N p_cosine), K shadow rays and N form-factor rays per patch.
    float misScale(uint32_t emitter, float cosReceiver, float distance, float cosEmitter) const;
    int raysPerPatch() const { return rays_; }
    int directSamples() const { return samples_; }
    // Lights that are not shapes of the scene.
    const std::vector<std::unique_ptr<Light>>& others() const { return others_; }

private:
    const PatchMesh& mesh_;
    int rays_, samples_;
    std::vector<uint32_t> emitters_;
    std::vector<float> cdf_;
    std::vector<float> probability_;  // per patch side; 0 for non-emitters
    std::vector<std::unique_ptr<Light>> others_;
};

}  // namespace photon
