#include "lights/point_light_choice.h"
#include <algorithm>

namespace photon {

PointLightChoice::PointLightChoice(const LightSampler& all) {
    std::vector<const Light*> lights;
    slot_.assign(all.size(), -1);
    for (size_t i = 0; i < all.size(); ++i) {
        const EmissionGeometry g = all.light(i).emissionGeometry();
        if (g.kind != EmissionGeometry::Kind::Point || isBlack(all.light(i).power())) continue;
        slot_[i] = int32_t(lights.size());
        lights.push_back(&all.light(i));
        index_.push_back(i);
        const float solidAngle = 2 * 3.14159265358979f * (1 - std::max(-1.0f, g.cosMax));
        beam_.push_back({g.position, g.frame.n, g.cosMax, average(all.light(i).power()) / solidAngle});
    }
    byPower_ = LightSampler(std::move(lights));
}

}  // namespace photon
