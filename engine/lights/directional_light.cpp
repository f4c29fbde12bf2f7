// Directional light: irradiance E (W/m^2) on surfaces facing it. Photons start on a disc
// covering the scene's bounding sphere, so its power is E pi R^2 (pbrt-v4 12.4).
#include "math/frame.h"
#include "math/sampling.h"
#include "lights/light_factories.h"

namespace photon {
namespace {

class DirectionalLight final : public Light {
public:
    DirectionalLight(const LightDescription& d, SceneSphere bounds)
        : frame_(Frame::fromNormal(normalize(d.direction))), irradiance_(d.irradiance), bounds_(bounds) {}

    Color power() const override { return irradiance_ * (kPi * bounds_.radius * bounds_.radius); }

    std::optional<LightSample> sampleIncident(Vec3, ReceiverSide, Vec2) const override {
        return LightSample{-frame_.n, std::numeric_limits<float>::infinity(), irradiance_};
    }

    std::optional<PhotonEmission> emitPhoton(Vec2 uPosition, Vec2) const override {
        return PhotonEmission{bounds_.pointOnDiscFacing(frame_, uPosition), frame_.n, power(), Vec3{}};
    }

    EmissionGeometry emissionGeometry() const override {
        return {EmissionGeometry::Kind::Parallel, {}, frame_, -1, bounds_};
    }
    Color emittedDensity(Vec3) const override { return irradiance_; }

private:
    Frame frame_;  // n: the direction light travels
    Color irradiance_;
    SceneSphere bounds_;
};

}  // namespace

std::unique_ptr<Light> makeDirectionalLight(const LightDescription& d, SceneSphere bounds) {
    return std::make_unique<DirectionalLight>(d, bounds);
}

}  // namespace photon
