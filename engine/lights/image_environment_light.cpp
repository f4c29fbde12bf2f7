// Environment light from an image (lights/environment_map.h), rotated into the world and
// scaled. Directions are sampled in proportion to luminance x solid angle, for shadow rays
// and photons alike. Photons start on a disc of the scene's bounding-sphere radius R
// facing their direction, pdf 1 / (pi R^2), so each carries L(w) pi R^2 / pdf(w)
// (pbrt-v4 12.5.2), and the light's power is pi R^2 times the integral of L over the sphere.
#include "lights/environment_map.h"
#include "lights/light_factories.h"

namespace photon {
namespace {

class ImageEnvironmentLight final : public Light {
public:
    ImageEnvironmentLight(const LightDescription& d, SceneSphere bounds)
        : map_(d.environment.image, d.environment.layout),
          scale_(environmentScale(d.environment, map_)),
          toWorld_(d.environment.toWorld),
          bounds_(bounds) {}

    Color power() const override { return map_.integral() * (scale_ * discArea()); }

    std::optional<LightSample> sampleIncident(Vec3, ReceiverSide, Vec2 u) const override {
        std::optional<EnvironmentMap::DirectionSample> s = map_.sample(u);
        if (!s) return std::nullopt;
        return LightSample{toWorld(s->direction), std::numeric_limits<float>::infinity(),
                           s->radiance * (scale_ / s->pdf), s->pdf};
    }

    float pdfIncident(Vec3, ReceiverSide, Vec3 wi) const override { return map_.pdf(toLocal(wi)); }

    std::optional<PhotonEmission> emitPhoton(Vec2 uPosition, Vec2 uDirection) const override {
        std::optional<EnvironmentMap::DirectionSample> s = map_.sample(uDirection);
        if (!s) return std::nullopt;
        Frame travel = Frame::fromNormal(-toWorld(s->direction));
        return PhotonEmission{bounds_.pointOnDiscFacing(travel, uPosition), travel.n,
                              s->radiance * (scale_ * discArea() / s->pdf), Vec3{}};
    }

    Color radianceFromDirection(Vec3, Vec3 d) const override { return map_.radiance(toLocal(d)) * scale_; }

private:
    float discArea() const { return kPi * bounds_.radius * bounds_.radius; }
    Vec3 toWorld(Vec3 local) const { return normalize(toWorld_.vector(local)); }
    Vec3 toLocal(Vec3 world) const { return normalize(toWorld_.inverseRotation(world)); }

    EnvironmentMap map_;
    float scale_;
    Transform toWorld_;
    SceneSphere bounds_;
};

}  // namespace

std::unique_ptr<Light> makeImageEnvironmentLight(const LightDescription& d, SceneSphere bounds) {
    return std::make_unique<ImageEnvironmentLight>(d, bounds);
}

}  // namespace photon
