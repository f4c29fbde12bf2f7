// What the lights that send from one point (point, profiled point, projection) share: the
// light arriving at a point p, their intensity toward p over the squared distance
// (delta lights: the sample's weight is irradiance, its pdf 0).
#pragma once
#include <cmath>
#include <optional>
#include "lights/light.h"

namespace photon {

// `intensityToward(w)`: the intensity (W/sr) in world direction w away from the light.
template <class IntensityToward>
std::optional<LightSample> samplePointEmitter(Vec3 position, Vec3 p, IntensityToward&& intensityToward) {
    const Vec3 toLight = position - p;
    const float dist2 = lengthSquared(toLight);
    if (dist2 <= 0) return std::nullopt;
    const Color intensity = intensityToward(-toLight);
    if (isBlack(intensity)) return std::nullopt;
    const float dist = std::sqrt(dist2);
    return LightSample{toLight / dist, dist, intensity / dist2};
}

}  // namespace photon
