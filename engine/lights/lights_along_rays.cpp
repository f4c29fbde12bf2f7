#include "lights/lights_along_rays.h"
#include <algorithm>

namespace photon {

LightsAlongRays::LightsAlongRays(const LightSampler& all) {
    std::vector<const Light*> lights;
    slot_.assign(all.size(), -1);
    for (size_t i = 0; i < all.size(); ++i) {
        const Light& light = all.light(i);
        if (isBlack(light.power()) || !light.sampledDirectly()) continue;
        const EmissionGeometry g = light.emissionGeometry();
        const std::optional<LightBounds> bounds = light.bounds();
        const bool area = light.pointDensity() > 0 && bounds;
        if (g.kind != EmissionGeometry::Kind::Point && !area) continue;
        slot_[i] = int32_t(lights.size());
        lights.push_back(&light);
        index_.push_back(i);
        constexpr float kPi = 3.14159265358979f;
        if (area) {
            // Its power over the whole sphere: for a flat one-sided light of radiance L and
            // area A, L A / 4, a quarter of its intensity along its normal.
            beam_.push_back({(bounds->lo + bounds->hi) * 0.5f, Vec3(0.0f), -1.0f, average(light.power()) / (4 * kPi), true});
            hasAreaLights_ = true;
        } else {
            const float solidAngle = 2 * kPi * (1 - std::max(-1.0f, g.cosMax));
            beam_.push_back({g.position, g.frame.n, g.cosMax, average(light.power()) / solidAngle, false});
        }
    }
    byPower_ = LightSampler(std::move(lights));
}

}  // namespace photon
