// Isotropic point light of intensity I (W/sr): power 4 pi I.
#include "math/sampling.h"
#include "lights/light_factories.h"

namespace photon {
namespace {

class PointLight final : public Light {
public:
    explicit PointLight(const LightDescription& d) : position_(d.position), intensity_(d.intensity) {}
    Color power() const override { return intensity_ * (4.0f * kPi); }

    std::optional<LightSample> sampleIncident(Vec3 p, ReceiverSide, Vec2) const override {
        Vec3 toLight = position_ - p;
        float dist2 = lengthSquared(toLight);
        if (dist2 <= 0) return std::nullopt;
        float dist = std::sqrt(dist2);
        return LightSample{toLight / dist, dist, intensity_ / dist2};
    }

    std::optional<PhotonEmission> emitPhoton(Vec2, Vec2 uDirection) const override {
        // Uniform directions: flux = I / (1 / 4 pi).
        return PhotonEmission{position_, sampleUniformSphere(uDirection), intensity_ * (4.0f * kPi), Vec3{}};
    }

    EmissionGeometry emissionGeometry() const override {
        return {EmissionGeometry::Kind::Point, position_, Frame::fromNormal({0, 0, 1}), -1, {}};
    }
    Color emittedDensity(Vec3) const override { return intensity_; }
    std::optional<LightBounds> bounds() const override {
        LightBounds b;
        b.lo = b.hi = position_;
        b.intensity = average(intensity_);
        return b;  // every direction (cosThetaO -1)
    }

private:
    Vec3 position_;
    Color intensity_;
};

}  // namespace

std::unique_ptr<Light> makePointLight(const LightDescription& d) {
    if (d.environment.image) return makeProfiledPointLight(d);
    return std::make_unique<PointLight>(d);
}

}  // namespace photon
