// A point light whose intensity varies with direction by an image over the sphere of
// directions (lights/environment_map.h, in the light's own frame): I(w) = intensity x
// texel(w) W/sr, pbrt-v4's goniometric light. Photons leave in directions drawn in
// proportion to the texels' luminance x solid angle, each carrying I(w) / pdf(w), so a
// profile of one bright texel is emitted with no variance from the profile; its power is
// intensity times the image's integral over the sphere.
#include "lights/environment_map.h"
#include "lights/light_factories.h"
#include "lights/point_emitter.h"

namespace photon {
namespace {

class ProfiledPointLight final : public Light {
public:
    explicit ProfiledPointLight(const LightDescription& d)
        : position_(d.position),
          intensity_(d.intensity * d.environment.scale),
          profile_(d.environment.image, d.environment.layout),
          toWorld_(d.environment.toWorld) {}

    Color power() const override { return intensity_ * profile_.integral(); }

    std::optional<LightSample> sampleIncident(Vec3 p, ReceiverSide, Vec2) const override {
        return samplePointEmitter(position_, p, [this](Vec3 w) { return emittedDensity(w); });
    }

    std::optional<PhotonEmission> emitPhoton(Vec2, Vec2 uDirection) const override {
        const std::optional<EnvironmentMap::DirectionSample> s = profile_.sample(uDirection);
        if (!s) return std::nullopt;
        return PhotonEmission{position_, normalize(toWorld_.vector(s->direction)), intensity_ * s->radiance / s->pdf,
                              Vec3{}};
    }

    EmissionGeometry emissionGeometry() const override {
        return {EmissionGeometry::Kind::Point, position_, Frame::fromNormal({0, 0, 1}), -1, {}};
    }
    Color emittedDensity(Vec3 w) const override {
        return intensity_ * profile_.radiance(normalize(toWorld_.inverseRotation(w)));
    }
    std::optional<LightBounds> bounds() const override {
        // As an isotropic point light of the same power (pbrt-v4's GoniometricLight::Bounds).
        LightBounds b;
        b.lo = b.hi = position_;
        b.intensity = average(power()) / (4.0f * kPi);
        return b;
    }

private:
    Vec3 position_;
    Color intensity_;
    EnvironmentMap profile_;
    Transform toWorld_;
};

}  // namespace

std::unique_ptr<Light> makeProfiledPointLight(const LightDescription& d) { return std::make_unique<ProfiledPointLight>(d); }

}  // namespace photon
