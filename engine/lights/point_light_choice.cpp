#include "lights/point_light_choice.h"

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
        beam_.push_back({g.position, g.frame.n, g.cosMax});
    }
    byPower_ = LightSampler(std::move(lights));
}

}  // namespace photon
